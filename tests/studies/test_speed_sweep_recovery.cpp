// The speed sweep's recovery (speed_sweep.hpp, R1-R3) on a case where plain continuation stops
// early: point feet seeded only at 0.6 m/s follow the low-speed curve, whose continuation fails at
// the minimal step near 0.79 m/s (bench/results/speed_sweep_bench.txt), so the seed's workflow
// leaves 0.8 and 0.9 m/s without a point. The recovery must give every speed a KKT point, say
// which step found it, and each point must be a KKT point when solved again from it. Where it may
// not open a curve, a speed keeps no point and gets a reason instead.
#include "cyclopt/studies/speed_sweep.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/nlp/solve.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace cyclopt;
using namespace cyclopt::continuation;
using namespace cyclopt::studies;

namespace {

const walker::GaitProblemOptions kProblem{walker::Objective::mechanical, 0.6, walker::Quadrature::trapezoid, {}};

// Point feet over 0.6-0.9 m/s, seeded at 0.6 m/s only, two starts.
SpeedSweepOptions stopping_early_case() {
  SpeedSweepOptions o;
  o.speeds = {0.6, 0.7, 0.8, 0.9};
  o.seed_speeds = {0.6};
  o.starts = 2;
  return o;
}

}  // namespace

TEST(SpeedSweepRecovery, ReachesTheSpeedsWherePlainContinuationStopped) {
  const walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset("point").spec);
  SpeedSweepOptions o = stopping_early_case();
  struct Reports final : SpeedSweepObserver {
    std::vector<SweepProgress> all;  // on_progress is called one at a time
    void on_progress(const SweepProgress& p) override { all.push_back(p); }
  } observer;
  const std::vector<SweepProgress>& reports = observer.all;
  const SpeedSweepResult r = speed_sweep(model, kProblem, o, observer);
  for (const ContinuationResult& run : r.runs)
    std::printf("run %.3f -> %.3f (curve %d): %s\n", run.points.front().parameter, run.points.back().parameter,
                run.points.front().curve_id, run.message.c_str());
  for (const BestPoint& b : r.best) std::printf("%.1f m/s: f %.6f, %s\n", b.speed, b.point.objective, describe(b).c_str());

  // The seed's workflow alone (curves from the seed multistart and their jumps) stops early.
  bool stopped_early = false;
  for (const ContinuationResult& run : r.runs)
    stopped_early = stopped_early || run.message.find("minimal step") != std::string::npos;
  EXPECT_TRUE(stopped_early);
  int recovered = 0;
  for (const BestPoint& b : r.best) {
    ASSERT_TRUE(b.found) << b.speed << " m/s: " << b.reason;
    if (b.origin.step != SweepStep::seed_multistart && b.origin.step != SweepStep::jump) ++recovered;
    // Independently: a fresh SQP solve from the stored point stops at once with the same f.
    walker::GaitProblemOptions at = kProblem;
    at.speed = b.speed;
    walker::GaitProblem p(model, at);
    nlp::SolverOptions so = nlp::seed_table_6_2_options();
    so.sqp.difference_hessian = true;
    const nlp::SolverSummary again = nlp::solve(p, so, b.point.x);
    EXPECT_TRUE(again.success()) << b.speed;
    EXPECT_LE(again.iterations, 5) << b.speed;
    EXPECT_NEAR(again.objective, b.point.objective, 1e-6 * b.point.objective) << b.speed;
  }
  EXPECT_GE(recovered, 1);
  EXPECT_FALSE(r.recoveries.empty());

  // Progress (sweep_progress.hpp): the phases in the order run, the multistart counted solve by
  // solve (its coarse starts, then their polish counted on: 20/20 -> 21/22, never back to 1/2),
  // grid speeds reached never decreasing up to all four, an ETA once a rate is measured.
  ASSERT_FALSE(reports.empty());
  EXPECT_EQ(reports.front().phase, SweepPhase::multistart);
  EXPECT_EQ(reports.front().phase_total, o.starts);
  int multistart_solves = 0, multistart_total = 0, phase_changes = 0, last_reached = 0;
  bool saw_continuation = false, saw_recovery = false, eta_measured = false;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    const SweepProgress& p = reports[i];
    EXPECT_EQ(p.speeds_total, 4);
    EXPECT_GE(p.speeds_reached, last_reached) << i;
    last_reached = p.speeds_reached;
    if (p.phase_total > 0) {
      EXPECT_LE(p.phase_done, p.phase_total) << i << " " << p.detail;
    }
    if (p.phase == SweepPhase::multistart && !saw_continuation) {
      EXPECT_GE(p.phase_done, multistart_solves) << i << " " << p.detail;
      multistart_solves = std::max(multistart_solves, p.phase_done);
      multistart_total = std::max(multistart_total, p.phase_total);
    }
    saw_continuation = saw_continuation || p.phase == SweepPhase::continuation;
    saw_recovery = saw_recovery || p.phase == SweepPhase::recovery;
    if (p.phase == SweepPhase::recovery) {
      EXPECT_TRUE(saw_continuation) << "recovery before any continuation";
    }
    if (i > 0 && (p.phase != reports[i - 1].phase || p.detail != reports[i - 1].detail)) ++phase_changes;
    if (std::isfinite(p.eta_seconds)) {
      EXPECT_GE(p.eta_seconds, 0.0) << i;
      eta_measured = true;
    }
  }
  EXPECT_GE(multistart_solves, o.starts);
  EXPECT_EQ(multistart_solves, multistart_total);
  EXPECT_TRUE(saw_continuation);
  EXPECT_TRUE(saw_recovery);
  EXPECT_TRUE(eta_measured);
  EXPECT_GE(phase_changes, 3);
  EXPECT_EQ(last_reached, 4);
  std::printf("%zu progress reports, %d phase changes\n", reports.size(), phase_changes);
}

// A KKT point that recovery finds but may not open a curve for (max_curves in use: the seed
// workflow's one curve) is not shown as found: the speed keeps no point and its reason says why
// and names the option.
TEST(SpeedSweepRecovery, ASpeedWithoutACurveKeepsNoPointAndSaysWhy) {
  const walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset("point").spec);
  SpeedSweepOptions o = stopping_early_case();
  o.max_curves = 1;
  const SpeedSweepResult r = speed_sweep(model, kProblem, o);
  ASSERT_EQ(r.best.size(), 4u);
  EXPECT_EQ(r.curves, 1);
  EXPECT_TRUE(r.best[0].found);
  EXPECT_TRUE(r.best[1].found);
  for (std::size_t i : {2u, 3u}) {
    const BestPoint& b = r.best[i];
    EXPECT_FALSE(b.found) << b.speed;
    EXPECT_NE(b.reason.find("max_curves (1)"), std::string::npos) << b.reason;
    EXPECT_EQ(describe(b), b.reason);
  }
  int unreached_tries = 0;
  for (const RecoveryAttempt& a : r.recoveries) {
    EXPECT_FALSE(a.found) << a.speed << " " << a.trigger;
    unreached_tries += a.trigger == "unreached";
  }
  EXPECT_EQ(unreached_tries, 2);  // each once: no curve was opened that could reach it since
}
