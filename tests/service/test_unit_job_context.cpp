// Work units (service/unit_job_context.hpp, issue 18): a unit's checkpoints live in its job's under
// "unit/<id>/" and it reads back only its own; its points and curves are the job's; it may not
// announce or split again; run_units_here runs units in order, stops with the job and names the
// unit that failed.
#include "cyclopt/service/unit_job_context.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace cyclopt::service {
namespace {

// A job context in memory: what the units did to their job.
class MemoryJob final : public JobContext {
 public:
  std::int64_t job_id() const override { return 7; }
  const JobLimits& limits() const override { return limits_; }
  void report_progress(const ProgressReport&) override {}
  void count_iterations(int) override {}
  void announce(int) override {}
  void add_curve(int curve, const std::string&, const std::string&) override { curves.push_back(curve); }
  bool store_point(const storage::SolutionPoint& p) override { return points.insert(p.key).second; }
  std::set<storage::PointKey> already_stored_points() override { return points; }
  void store_checkpoint(const std::string& key, const std::string& value) override { checkpoints[key] = value; }
  std::map<std::string, std::string> stored_checkpoints() override { return checkpoints; }
  StopReason stop_reason() override { return stop; }

  JobLimits limits_;
  std::vector<int> curves;
  std::set<storage::PointKey> points;
  std::map<std::string, std::string> checkpoints;
  StopReason stop = StopReason::none;
};

TEST(UnitJobContext, KeepsCheckpointsPerUnitAndPointsInTheJob) {
  MemoryJob job;
  job.checkpoints["run/0"] = "the job's own";
  UnitJobContext a(job, {"foot-0", 0}), b(job, {"foot-1", 1});
  a.store_checkpoint("run/0", "a's run");
  b.store_checkpoint("run/0", "b's run");
  b.store_checkpoint("swept foot", "b's result");
  EXPECT_EQ(job.checkpoints.at("unit/foot-0/run/0"), "a's run");
  EXPECT_EQ(job.checkpoints.at("unit/foot-1/run/0"), "b's run");
  EXPECT_EQ(job.checkpoints.at("run/0"), "the job's own");
  EXPECT_EQ(a.stored_checkpoints(), (std::map<std::string, std::string>{{"run/0", "a's run"}}));
  EXPECT_EQ(b.stored_checkpoints(),
            (std::map<std::string, std::string>{{"run/0", "b's run"}, {"swept foot", "b's result"}}));
  storage::SolutionPoint p;
  p.key = {2, 0};
  EXPECT_TRUE(b.store_point(p));
  EXPECT_FALSE(a.store_point(p));  // one job, one set of keys
  a.add_curve(1, "foot 0", "speed");
  EXPECT_EQ(job.curves, std::vector<int>{1});
  EXPECT_THROW(a.announce(3), std::logic_error);
  EXPECT_THROW(a.run_units({{"x", 0}}, [](const WorkUnit&, JobContext&) {}), std::logic_error);
}

TEST(UnitJobContext, RunUnitsHereRunsInOrderStopsWithTheJobAndNamesAFailedUnit) {
  MemoryJob job;
  std::vector<std::string> ran;
  const std::vector<WorkUnit> units{{"foot-0", 0}, {"foot-1", 1}, {"foot-2", 2}};
  job.run_units(units, [&](const WorkUnit& u, JobContext& ctx) {
    ran.push_back(u.id);
    ctx.store_checkpoint("done", std::to_string(u.index));
  });
  EXPECT_EQ(ran, (std::vector<std::string>{"foot-0", "foot-1", "foot-2"}));
  EXPECT_EQ(job.checkpoints.at("unit/foot-2/done"), "2");

  ran.clear();
  job.run_units(units, [&](const WorkUnit& u, JobContext&) {
    ran.push_back(u.id);
    if (u.index == 1) job.stop = StopReason::cancelled;
  });
  EXPECT_EQ(ran, (std::vector<std::string>{"foot-0", "foot-1"}));  // no unit starts once the job stops

  job.stop = StopReason::none;
  try {
    job.run_units(units, [](const WorkUnit& u, JobContext&) {
      if (u.index == 1) throw std::runtime_error("no starting gait at 0.3 m/s");
    });
    ADD_FAILURE() << "a failed unit did not fail the job";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "work unit foot-1: no starting gait at 0.3 m/s");
  }
}

}  // namespace
}  // namespace cyclopt::service
