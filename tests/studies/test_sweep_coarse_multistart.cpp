// SpeedSweepOptions::coarse_points (speed_sweep.hpp): a batch of perturbed starts is solved on a
// coarse quadrature grid first and its distinct optima are polished at the model's P, so what the
// sweep continues is a KKT point of the model's problem, not of the coarse one.
#include "cyclopt/studies/speed_sweep.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/nlp/solve.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace cyclopt;
using namespace cyclopt::studies;

namespace {

const walker::GaitProblemOptions kProblem{walker::Objective::mechanical, 0.6, walker::Quadrature::trapezoid, {}};

walker::WalkerModel<double> point_feet(int points) {
  walker::WalkingConstants constants;
  constants.points = points;
  return walker::make_walker_model(foot::foot_preset("point").spec, constants);
}

SpeedSweepOptions coarse_sweep(int coarse_points) {
  SpeedSweepOptions o;
  o.speeds = {0.6, 0.7};
  o.seed_speeds = {0.6};
  o.starts = 2;
  o.recover = false;
  o.coarse_points = coarse_points;
  return o;
}

// Iterations the corrector's SQP needs from x at P points (0: x is a KKT point there).
int iterations_from(const Eigen::VectorXd& x, int points) {
  walker::GaitProblem problem(point_feet(points), kProblem);
  const nlp::SolverSummary s = nlp::solve(problem, ContinuationOptions{}.corrector, x);
  EXPECT_TRUE(s.success()) << s.message;
  return s.iterations;
}

}  // namespace

TEST(SweepCoarseMultistart, ContinuesOptimaPolishedAtTheModelsGrid) {
  const SpeedSweepResult r = speed_sweep(point_feet(200), kProblem, coarse_sweep(50));
  ASSERT_FALSE(r.runs.empty());
  const CurvePoint& seed_optimum = r.runs.front().points.front();
  ASSERT_TRUE(seed_optimum.converged) << seed_optimum.corrector.message;
  EXPECT_EQ(r.origins.front().step, SweepStep::seed_multistart);
  // The continuation's first solve starts on the multistart's optimum: a KKT point at P = 200 ...
  EXPECT_EQ(seed_optimum.corrector.iterations, 0);
  EXPECT_EQ(iterations_from(seed_optimum.x, 200), 0);
  // ... which is not one of the coarse problem (the polish did work).
  EXPECT_GT(iterations_from(seed_optimum.x, 50), 0);
  // Both starts at P = 50, then one polish per distinct coarse optimum.
  EXPECT_GT(r.multistart_solves, 2);
  EXPECT_LE(r.multistart_solves, 4);
  for (const BestPoint& b : r.best) EXPECT_TRUE(b.found) << b.speed << " m/s: " << b.reason;
}

TEST(SweepCoarseMultistart, OffWhenNotCoarserThanTheModel) {
  // coarse_points >= P: every start at P, exactly `starts` solves.
  const SpeedSweepResult r = speed_sweep(point_feet(50), kProblem, coarse_sweep(50));
  EXPECT_EQ(r.multistart_solves, 2);
  for (const BestPoint& b : r.best) EXPECT_TRUE(b.found) << b.speed << " m/s: " << b.reason;
}

TEST(SweepCoarseMultistart, RefusesANegativeCoarseGrid) {
  try {
    speed_sweep(point_feet(50), kProblem, coarse_sweep(-1));
    FAIL() << "coarse_points -1 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("coarse_points"), std::string::npos) << e.what();
  }
}
