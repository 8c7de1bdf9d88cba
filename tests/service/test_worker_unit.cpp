// cyclopt-worker (server/cyclopt_worker_main.cpp) runs a unit from the spec text the server stored,
// parsed once in its own process: a spec that is not valid there ends the unit with an error in
// done.json naming the field (exit 0, as for any failed job; the server then fails the job with
// it), and a valid one runs. A work unit of a job (JobKind::run_unit) computes only its part: one
// foot of a comparison stores that foot's curve and its sweep result, nothing of the other feet.
// No Slurm needed: the test writes the spool itself.
#include "remote/unit_spool.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace cyclopt::server::remote {
namespace {

std::string foot_sweep_spec(int samples) {
  return nlohmann::json{{"scene", "walker"},
                        {"task", "foot_sweep"},
                        {"foot", "P2-shoes-left-HMT"},
                        {"samples", samples},
                        {"sweep", {{"parameter", "density"}, {"values", "10:10:30"}}}}
      .dump();
}

class WorkerUnit : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("cyclopt_worker_unit_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Writes a unit with `spec_json` for `task`, runs cyclopt-worker on it; returns its spool.
  UnitSpool run_unit(const std::string& name, const std::string& task, const std::string& spec_json,
                     std::optional<service::WorkUnit> work_unit = std::nullopt) {
    UnitSpool spool(dir_ / name);
    spool.create();
    UnitSpec unit;
    unit.job_id = 1;
    unit.task = task;
    unit.spec_json = spec_json;
    unit.unit = work_unit;
    spool.write_spec(unit);
    spool.write_stored_keys({});
    spool.write_checkpoints({});
    const std::string command = std::string(CYCLOPT_WORKER) + " --unit '" + spool.dir().string() + "' > '" +
                                (dir_ / (name + ".log")).string() + "' 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return spool;
  }

  std::filesystem::path dir_;
};

TEST_F(WorkerUnit, AStoredSpecThatIsNotValidHereBecomesTheUnitsError) {
  const struct {
    std::string name, task, spec, error;
  } cases[] = {
      {"malformed", "foot_sweep", "{\"scene\": \"walker\", \"task\": ",
       "spec_json: the job spec is not valid in this cyclopt-worker (spec_json: malformed JSON"},
      {"out_of_range", "foot_sweep", foot_sweep_spec(500),
       "spec_json: the job spec is not valid in this cyclopt-worker (samples: must be in [2, 200], got 500)"},
      {"other_task", "giant_swing", foot_sweep_spec(13), "unit.json: task 'giant_swing' but its spec's task is 'foot_sweep'"},
  };
  for (const auto& c : cases) {
    const UnitSpool spool = run_unit(c.name, c.task, c.spec);
    const auto outcome = spool.read_outcome();
    ASSERT_TRUE(outcome) << c.name << ": no done.json";
    EXPECT_EQ(outcome->error.rfind(c.error, 0), 0u) << c.name << ": " << outcome->error;
    EXPECT_TRUE(spool.read_events(0).empty()) << c.name << ": the unit ran";
  }
}

TEST_F(WorkerUnit, AValidStoredSpecRuns) {
  const UnitSpool spool = run_unit("valid", "foot_sweep", foot_sweep_spec(5));
  const auto outcome = spool.read_outcome();
  ASSERT_TRUE(outcome);
  EXPECT_EQ(outcome->error, "");
  EXPECT_EQ(outcome->stop, service::StopReason::none);
  int points = 0;
  for (const auto& [n, e] : spool.read_events(0)) points += e.type == UnitEvent::Type::point;
  EXPECT_EQ(points, 3);
}

TEST_F(WorkerUnit, AWorkUnitOfAJobWhoseKindDoesNotSplitIsAnError) {
  const UnitSpool spool = run_unit("no_units", "foot_sweep", foot_sweep_spec(5), service::WorkUnit{"part-0", 0});
  const auto outcome = spool.read_outcome();
  ASSERT_TRUE(outcome);
  EXPECT_EQ(outcome->error, "unit.json: work unit 'part-0' of task 'foot_sweep', which does not split into units");
  EXPECT_TRUE(spool.read_events(0).empty());
}

TEST_F(WorkerUnit, AComparisonFootUnitSweepsOnlyItsFoot) {
  const std::string spec = nlohmann::json{{"scene", "walker"},
                                          {"task", "foot_comparison"},
                                          {"speeds", "1.0:0.1:1.1"},
                                          {"points", 50},
                                          {"feet", {"P1-shoes-left-HM-SG"}},
                                          {"multistart", {{"starts", 2}, {"seed", 3}, {"scale", 0.02}}},
                                          {"continuation", {{"seed_speeds", 1.0}}}}
                               .dump();
  const UnitSpool spool = run_unit("foot_0", "foot_comparison", spec, service::WorkUnit{"foot-0", 0});
  const auto outcome = spool.read_outcome();
  ASSERT_TRUE(outcome);
  EXPECT_EQ(outcome->error, "");
  std::set<int> curves;
  int points = 0;
  std::vector<std::string> checkpoints;
  for (const auto& [n, e] : spool.read_events(0)) {
    EXPECT_NE(e.type, UnitEvent::Type::announce) << "a unit announced points";
    if (e.type == UnitEvent::Type::point) curves.insert(e.point.key.curve_index), ++points;
    if (e.type == UnitEvent::Type::checkpoint && e.checkpoint_key.rfind("solve/", 0) != 0 &&
        e.checkpoint_key.rfind("run/", 0) != 0 && e.checkpoint_key.rfind("run_state/", 0) != 0)  // the journal's
      checkpoints.push_back(e.checkpoint_key);
  }
  EXPECT_EQ(curves, (std::set<int>{1}));  // curve 1 + 0: the reference (point feet) only
  EXPECT_EQ(points, 2);                    // its best point at both speeds
  // The sweep result the job reads, under the unit's own key (the server adds "unit/foot-0/").
  EXPECT_EQ(checkpoints, (std::vector<std::string>{"swept foot"}));
}

}  // namespace
}  // namespace cyclopt::server::remote
