// Work units (service/unit_job_context.hpp, issue 18): a unit's checkpoints live in its job's under
// "unit/<id>/" and it reads back only its own; its points and curves are the job's; it may not
// announce or split again; run_units_here runs units in order, stops with the job and names the
// unit that failed; run_units_in_parallel runs them at once, each exactly once, and a failed unit
// stops the one beside it and fails the job; a comparison's foot unit counts in its progress the
// feet already swept, whichever unit swept them.
#include "cyclopt/service/unit_job_context.hpp"

#include "cyclopt/jobs/foot/foot_kinds.hpp"
#include "cyclopt/service/job_spec.hpp"
#include "memory_job.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <string>
#include <vector>

namespace cyclopt::service {
namespace {

using namespace cyclopt::jobs;

// Waits up to 10 s for `done`; false on timeout (so a broken runner fails the test, not hangs it).
template <class Done>
bool wait_for(Done done) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!done())
    if (std::chrono::steady_clock::now() > until) return false;
    else std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return true;
}

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

TEST(UnitJobContext, RunUnitsInParallelRunsTwoAtOnceEachExactlyOnce) {
  MemoryJob job;
  std::atomic<int> running{0}, most{0};
  std::mutex mutex;
  std::multiset<std::string> ran;
  const std::vector<WorkUnit> units{{"foot-0", 0}, {"foot-1", 1}, {"foot-2", 2}, {"foot-3", 3}, {"foot-4", 4}};
  run_units_in_parallel(units, [&](const WorkUnit& u, JobContext& ctx) {
    const int now = ++running;
    most = std::max(most.load(), now);
    // A unit waits until a second one runs beside it (the last unit has no partner left).
    wait_for([&] { return most.load() >= 2 || u.index == 4; });
    {
      const std::lock_guard<std::mutex> lock(mutex);
      ran.insert(u.id);
    }
    ctx.store_checkpoint("done", std::to_string(u.index));
    --running;
  }, job, 2);
  EXPECT_EQ(most.load(), 2);
  EXPECT_EQ(ran, (std::multiset<std::string>{"foot-0", "foot-1", "foot-2", "foot-3", "foot-4"}));
  for (const WorkUnit& u : units) EXPECT_EQ(job.checkpoints.at("unit/" + u.id + "/done"), std::to_string(u.index));
}

TEST(UnitJobContext, RunUnitsInParallelStopsTheSiblingOfAFailedUnitAndNamesIt) {
  MemoryJob job;
  std::atomic<bool> sibling_saw_stop{false};
  std::atomic<int> started{0};
  const std::vector<WorkUnit> units{{"foot-0", 0}, {"foot-1", 1}, {"foot-2", 2}, {"foot-3", 3}};
  try {
    run_units_in_parallel(units, [&](const WorkUnit& u, JobContext& ctx) {
      ++started;
      if (u.index == 0) {
        wait_for([&] { return started.load() >= 2; });  // foot-1 is running
        throw std::runtime_error("no starting gait at 0.3 m/s");
      }
      sibling_saw_stop = wait_for([&] { return ctx.stop_reason() != StopReason::none; });
    }, job, 2);
    ADD_FAILURE() << "a failed unit did not fail the job";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "work unit foot-0: no starting gait at 0.3 m/s");
  }
  EXPECT_TRUE(sibling_saw_stop.load());
  EXPECT_EQ(started.load(), 2);  // foot-2 and foot-3 never started
  EXPECT_EQ(job.stop_reason(), StopReason::none);  // the job's own reason is untouched
}

TEST(UnitJobContext, RunUnitsInParallelStopsWithTheJob) {
  MemoryJob job;
  std::atomic<int> started{0};
  const std::vector<WorkUnit> units{{"foot-0", 0}, {"foot-1", 1}, {"foot-2", 2}, {"foot-3", 3}};
  run_units_in_parallel(units, [&](const WorkUnit&, JobContext&) {
    if (++started == 2) job.stop = StopReason::shutdown;
  }, job, 2);
  EXPECT_LE(started.load(), 3);  // at most the unit the other thread had already taken
}

// Units may run at once or in any order: a foot unit's progress counts the speeds of the feet whose
// best points are stored, not of the feet before it in the list. Foot 1 (curve 2) is swept here
// before foot 0 (point feet) runs.
TEST(UnitJobContext, AComparisonFootUnitsProgressCountsTheFeetAlreadySwept) {
  JobKindRegistry kinds;
  kinds.add(foot_comparison_kind());
  const ValidatedJobSpec spec = validate_job_spec({{"scene", "walker"},
                                                   {"task", "foot_comparison"},
                                                   {"speeds", "1.0:0.1:1.1"},
                                                   {"points", 50},
                                                   {"feet", {"P1-shoes-left-HM-SG"}},
                                                   {"multistart", {{"starts", 2}, {"seed", 3}, {"scale", 0.02}}},
                                                   {"continuation", {{"seed_speeds", 1.0}}}},
                                                  kinds);
  MemoryJob job;
  job.points = {{2, 0}, {2, 1}};
  const WorkUnit unit{"foot-0", 0};
  UnitJobContext ctx(job, unit);
  spec.kind->run_unit(*spec.spec, unit, ctx);
  ASSERT_FALSE(job.reports.empty());
  for (const ProgressReport& r : job.reports) {
    EXPECT_EQ(r.points_total, 4);  // two feet, two speeds
    EXPECT_GE(r.points_done, 2) << r.message;  // foot 1's two speeds
    EXPECT_LE(r.points_done, 4) << r.message;
  }
  EXPECT_EQ(job.reports.back().points_done, 4);  // and both of its own
  EXPECT_TRUE(job.points.count({1, 0}) && job.points.count({1, 1}));  // its best points, curve 1 + 0
}

}  // namespace
}  // namespace cyclopt::service
