// Resume of an interrupted speed sweep (issue 19 item 5; studies/sweep_journal.hpp): a sweep
// stopped part-way and run again with the journal of the stopped attempt solves only what that
// attempt had not finished, and selects exactly the points of an uninterrupted sweep. The journal
// here is a map of the same JSON texts the service stores (service/sweep_checkpoints.hpp), so the
// round trip through the stored form is part of what is checked.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/jobs/walker/sweep_checkpoints.hpp"
#include "cyclopt/records/json_fields.hpp"
#include "cyclopt/studies/speed_sweep.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <string>

using namespace cyclopt;
using namespace cyclopt::studies;

namespace {

// The JobContext side of the journal, in memory, as the sweep's observer; the sweep stops after
// stop_after points.
struct MemoryJournal final : SpeedSweepObserver {
  std::map<std::string, std::string> texts;
  std::mutex mutex;
  int recorded = 0;
  int stop_after = std::numeric_limits<int>::max();

  bool on_point(const continuation::CurvePoint&) override { return --stop_after > 0; }
  SweepJournal journal() override {
    SweepJournal j;
    j.find_solve = [this](int b, int s) -> std::optional<nlp::SolverSummary> {
      const std::lock_guard lock(mutex);
      const auto it = texts.find("solve/" + std::to_string(b) + "/" + std::to_string(s));
      if (it == texts.end()) return std::nullopt;
      return jobs::summary_from_json(nlohmann::json::parse(it->second));
    };
    j.record_solve = [this](int b, int s, const nlp::SolverSummary& run) {
      const std::lock_guard lock(mutex);
      texts["solve/" + std::to_string(b) + "/" + std::to_string(s)] = jobs::summary_to_json(run).dump();
      ++recorded;
    };
    j.find_run = [this](int n) -> std::optional<continuation::ContinuationResult> {
      const auto it = texts.find("run/" + std::to_string(n));
      if (it == texts.end()) return std::nullopt;
      return jobs::run_from_json(nlohmann::json::parse(it->second));
    };
    j.record_run = [this](int n, const continuation::ContinuationResult& r) {
      texts["run/" + std::to_string(n)] = jobs::run_to_json(r).dump();
      ++recorded;
    };
    if (!with_run_states) return j;
    j.find_run_state = [this](int n) -> std::optional<continuation::RunState> {
      const auto it = texts.find("run_state/" + std::to_string(n));
      if (it == texts.end() || texts.count("run/" + std::to_string(n))) return std::nullopt;
      ++states_found;
      return jobs::run_state_from_json(nlohmann::json::parse(it->second));
    };
    j.record_run_state = [this](int n, const continuation::RunState& r) {
      const std::lock_guard lock(mutex);
      texts["run_state/" + std::to_string(n)] = jobs::run_state_to_json(r).dump();
    };
    return j;
  }
  bool with_run_states = true;
  int states_found = 0;  // unfinished runs found with a state
};

struct SweepCase {
  walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset("point").spec);
  walker::GaitProblemOptions problem{walker::Objective::mechanical, 0.6, walker::Quadrature::trapezoid, {}};
  SpeedSweepOptions options;
  // The recovery test's case (test_speed_sweep_recovery.cpp): a seed multistart, continuation
  // stopping at the minimal step, then R1-R3 with runs of their own - every kind of journal entry.
  SweepCase() {
    options.speeds = {0.6, 0.7, 0.8, 0.9};
    options.seed_speeds = {0.6};
    options.starts = 2;
  }
};

void expect_same_best(const SpeedSweepResult& a, const SpeedSweepResult& b) {
  ASSERT_EQ(a.best.size(), b.best.size());
  for (std::size_t i = 0; i < a.best.size(); ++i) {
    ASSERT_EQ(a.best[i].found, b.best[i].found) << a.best[i].speed;
    if (!a.best[i].found) continue;
    EXPECT_EQ(a.best[i].point.objective, b.best[i].point.objective) << a.best[i].speed;
    EXPECT_EQ(a.best[i].point.curve_id, b.best[i].point.curve_id) << a.best[i].speed;
    EXPECT_EQ((a.best[i].point.x - b.best[i].point.x).lpNorm<Eigen::Infinity>(), 0.0) << a.best[i].speed;
  }
  EXPECT_EQ(a.curves, b.curves);
}

}  // namespace

TEST(SweepResume, AnInterruptedSweepSolvesOnlyWhatItHadNotFinished) {
  const SweepCase c;
  const SpeedSweepResult whole = speed_sweep(c.model, c.problem, c.options);
  ASSERT_GE(whole.runs.size(), 2u);
  int total_points = 0;
  for (const continuation::ContinuationResult& run : whole.runs) total_points += static_cast<int>(run.points.size());

  // Attempt 1: stopped after three quarters of the points (a crash leaves the same journal: what was
  // recorded before it).
  MemoryJournal memory;
  const SpeedSweepOptions& o = c.options;
  memory.stop_after = 3 * total_points / 4;
  const SpeedSweepResult first = speed_sweep(c.model, c.problem, o, memory);
  ASSERT_GT(memory.recorded, 0);
  EXPECT_EQ(first.resumed_solves + first.resumed_runs, 0);

  // Attempt 2 resumes: the finished solves and runs are taken over, the selection is the
  // uninterrupted one, bit for bit.
  memory.stop_after = std::numeric_limits<int>::max();
  const SpeedSweepResult second = speed_sweep(c.model, c.problem, o, memory);
  std::printf("uninterrupted: %d solves, %d runs; attempt 1: %d solves, %d runs; attempt 2: %d solves + %d resumed, "
              "%d runs + %d resumed\n",
              whole.multistart_solves, whole.computed_runs, first.multistart_solves, first.computed_runs,
              second.multistart_solves, second.resumed_solves, second.computed_runs, second.resumed_runs);
  EXPECT_GT(second.resumed_solves, 0);
  EXPECT_GT(second.resumed_runs, 0);
  EXPECT_LT(second.multistart_solves, whole.multistart_solves);
  EXPECT_EQ(second.multistart_solves + second.resumed_solves, whole.multistart_solves);
  EXPECT_EQ(second.computed_runs + second.resumed_runs, whole.computed_runs);
  expect_same_best(whole, second);

  // Attempt 3 finds everything recorded: nothing is solved again.
  const SpeedSweepResult third = speed_sweep(c.model, c.problem, o, memory);
  EXPECT_EQ(third.multistart_solves, 0);
  EXPECT_EQ(third.computed_runs, 0);
  expect_same_best(whole, third);
}

TEST(SweepResume, CheckpointTextsRoundTripEveryField) {
  nlp::SolverSummary s;
  s.termination = nlp::Termination::acceptable;
  s.message = "ok \"quoted\"";
  s.iterations = 7;
  s.objective = 0.1 + 0.2;  // not representable in few digits
  s.kkt_error = std::nan("");
  s.x = Eigen::VectorXd::LinSpaced(5, -1.0 / 3.0, 2.0 / 7.0);
  s.bound_multipliers = Eigen::VectorXd::Constant(2, 1e-300);
  const nlp::SolverSummary back = jobs::summary_from_json(nlohmann::json::parse(jobs::summary_to_json(s).dump()));
  EXPECT_EQ(back.termination, s.termination);
  EXPECT_EQ(back.message, s.message);
  EXPECT_EQ(back.iterations, s.iterations);
  EXPECT_EQ(back.objective, s.objective);
  EXPECT_TRUE(std::isnan(back.kkt_error));
  EXPECT_EQ(back.x, s.x);
  EXPECT_EQ(back.bound_multipliers, s.bound_multipliers);
  EXPECT_EQ(back.equality_multipliers.size(), 0);
  nlohmann::json bad = jobs::summary_to_json(s);
  bad["termination"] = "no_such_end";
  EXPECT_THROW(jobs::summary_from_json(bad), records::RecordError);
}

// An attempt stopped in the middle of a continuation run leaves where the run stood after its last
// converged point (run_state/<n>, issue 57): the next attempt goes on from there - it spends fewer
// solver iterations than an attempt without run states, the rest of its work being the same - and
// selects the uninterrupted sweep's points, bit for bit.
TEST(SweepResume, AnInterruptedRunGoesOnFromItsLastConvergedPoint) {
  const SweepCase c;
  const SpeedSweepResult whole = speed_sweep(c.model, c.problem, c.options);
  int total_points = 0;
  for (const continuation::ContinuationResult& run : whole.runs) total_points += static_cast<int>(run.points.size());
  long iterations[2] = {0, 0};  // of the resumed attempt: without, with run states
  for (const bool states : {false, true}) {
    MemoryJournal memory;
    memory.with_run_states = states;
    // Stopped at the middle point: inside a run (the seed multistart's points come first).
    memory.stop_after = total_points / 2;
    speed_sweep(c.model, c.problem, c.options, memory);
    memory.stop_after = std::numeric_limits<int>::max();
    SpeedSweepOptions counted = c.options;
    counted.continuation.corrector.on_iteration = [&](const nlp::IterationReport&) {
      ++iterations[states];
      return true;
    };
    const SpeedSweepResult resumed = speed_sweep(c.model, c.problem, counted, memory);
    if (states) {
      EXPECT_GT(memory.states_found, 0);
    }
    expect_same_best(whole, resumed);
  }
  std::printf("solver iterations of the resumed attempt: %ld resuming the run from its start, %ld from its last point\n",
              iterations[0], iterations[1]);
  EXPECT_LT(iterations[1], iterations[0]);
}
