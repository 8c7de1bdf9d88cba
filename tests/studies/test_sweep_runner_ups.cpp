// SpeedSweepOptions::runner_ups (speed_sweep.hpp, step 2b): the further optima of a seed-speed
// multistart are continued while they are the best known. With recovery off the step only adds
// curves, so no speed may get a worse point, and a runner-up's run must stop at the first grid
// speed where a curve found before it is at least as good.
#include "cyclopt/studies/speed_sweep.hpp"
#include "cyclopt/foot/foot_presets.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <stdexcept>

using namespace cyclopt;
using namespace cyclopt::continuation;
using namespace cyclopt::studies;

namespace {

const walker::GaitProblemOptions kProblem{walker::Objective::mechanical, 0.6, walker::Quadrature::trapezoid, {}};

SpeedSweepResult sweep(int runner_ups) {
  walker::WalkingConstants constants;
  constants.points = 100;
  const walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset("point").spec, constants);
  SpeedSweepOptions o;
  o.speeds = {0.5, 0.6, 0.7, 0.8};
  o.seed_speeds = {0.6};
  o.starts = 6;
  o.coarse_points = 0;
  o.recover = false;
  o.runner_ups = runner_ups;
  o.runner_up_margin = 1.0;
  return speed_sweep(model, kProblem, o);
}

int seed_curves(const SpeedSweepResult& r) {
  int n = 0;
  for (const CurveOrigin& o : r.origins) n += o.step == SweepStep::seed_multistart;
  return n;
}

// The lowest objective at grid speed v over the converged points of curves below `curve`.
double best_before(const SpeedSweepResult& r, int curve, double v) {
  double best = INFINITY;
  for (const ContinuationResult& run : r.runs)
    for (const CurvePoint& p : run.points)
      if (p.converged && p.on_grid && p.curve_id < curve && std::abs(p.parameter - v) < 1e-12) best = std::min(best, p.objective);
  return best;
}

}  // namespace

TEST(SweepRunnerUps, AddCurvesThatAreBestWhereTheyRun) {
  const SpeedSweepResult without = sweep(0), with = sweep(3);
  EXPECT_EQ(seed_curves(without), 1);
  ASSERT_GE(seed_curves(with), 2) << "the seed multistart found one optimum only: no runner-up to test";
  ASSERT_EQ(with.best.size(), without.best.size());
  int found_without = 0;
  for (std::size_t i = 0; i < with.best.size(); ++i) {
    if (!without.best[i].found) continue;
    ++found_without;
    ASSERT_TRUE(with.best[i].found) << with.best[i].speed;
    EXPECT_LE(with.best[i].point.objective, without.best[i].point.objective + 1e-12) << with.best[i].speed;
  }
  EXPECT_GE(found_without, 2);
  // A runner-up's run passes a grid speed (other than its start) only where its point beats every
  // curve found before it, and where it stops as superseded a curve found before it is as good.
  int stops = 0;
  for (const ContinuationResult& run : with.runs) {
    const int curve = run.points.front().curve_id;
    if (curve == 0 || with.origins[static_cast<std::size_t>(curve)].step != SweepStep::seed_multistart) continue;
    const double start = run.points.front().parameter;
    const bool superseded = run.message.find("another curve is as good") != std::string::npos;
    int last_on_grid = -1;
    for (int k = 0; k < static_cast<int>(run.points.size()); ++k)
      if (run.points[k].converged && run.points[k].on_grid && run.points[k].curve_id == curve) last_on_grid = k;
    for (int k = 0; k <= last_on_grid; ++k) {
      const CurvePoint& p = run.points[k];
      if (!p.converged || !p.on_grid || p.curve_id != curve || std::abs(p.parameter - start) < 1e-12) continue;
      const double known = best_before(with, curve, p.parameter);
      if (k < last_on_grid) {
        EXPECT_LT(p.objective, known) << "curve " << curve << " passed " << p.parameter;
      } else if (superseded) {
        EXPECT_GE(p.objective, known - 1e-6 * std::max(1.0, std::abs(known))) << "curve " << curve << " stopped at " << p.parameter;
        ++stops;
      }
    }
  }
  EXPECT_GE(stops, 1) << "no runner-up run stopped where a known curve is as good";
}

TEST(SweepRunnerUps, RefusesNegativeSettings) {
  SpeedSweepOptions o;
  o.speeds = {0.5, 0.6};
  const walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset("point").spec);
  o.runner_ups = -1;
  EXPECT_THROW(speed_sweep(model, kProblem, o), std::invalid_argument);
  o.runner_ups = 1;
  o.runner_up_margin = -0.1;
  EXPECT_THROW(speed_sweep(model, kProblem, o), std::invalid_argument);
}
