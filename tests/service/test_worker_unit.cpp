// cyclopt-worker (server/cyclopt_worker_main.cpp) runs a unit from the spec text the server stored,
// parsed once in its own process: a spec that is not valid there ends the unit with an error in
// done.json naming the field (exit 0, as for any failed job; the server then fails the job with
// it), and a valid one runs. No Slurm needed: the test writes the spool itself.
#include "remote/unit_spool.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

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
  UnitSpool run_unit(const std::string& name, const std::string& task, const std::string& spec_json) {
    UnitSpool spool(dir_ / name);
    spool.create();
    UnitSpec unit;
    unit.job_id = 1;
    unit.task = task;
    unit.spec_json = spec_json;
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

}  // namespace
}  // namespace cyclopt::server::remote
