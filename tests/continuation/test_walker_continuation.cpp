// The QPSQP continuation (seed 001, Algorithm 2) on the point-foot walker over the mean speed.
#include "cyclopt/continuation/continuation_solver.hpp"
#include "cyclopt/continuation/walker_family.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"

#include <gtest/gtest.h>

#include <cstdio>

using namespace cyclopt;
using namespace cyclopt::continuation;

namespace {

struct PointFeet {
  walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset("point").spec);
  walker::GaitProblemOptions problem{walker::Objective::mechanical, 1.0, walker::Quadrature::trapezoid, {}};
  walker::GaitOptimum start = walker::optimise_gait(model, problem, nlp::seed_table_6_2_options());
};

const PointFeet& point_feet() {
  static const PointFeet p;
  return p;
}

void print(const ContinuationResult& r) {
  for (const CurvePoint& p : r.points)
    std::printf("p %.4f curve %d grid %d ok %d f %.6f corr %d pred %d/%d kappa %.3f Delta %.4f %.2fs\n", p.parameter,
                p.curve_id, p.on_grid, p.converged, p.objective, p.corrector.iterations, p.predictor_attempts,
                p.predictor_steps, p.kappa, p.trust_region, p.seconds);
  std::printf("%s; %zu jumps, %.1f s\n", r.message.c_str(), r.jumps.size(), r.seconds);
}

}  // namespace

TEST(WalkerContinuation, BackAndForthReturnsToTheSameOptimum) {
  const PointFeet& pf = point_feet();
  ASSERT_TRUE(pf.start.summary.success());
  const ParametricProblem family = walker_family(pf.model, pf.problem, "speed");
  const ContinuationOptions o;
  const ContinuationResult up = continue_solution(family, pf.start.z, {1.0, 1.1, 1.2}, o);
  print(up);
  ASSERT_TRUE(up.finished);
  const ContinuationResult down = continue_solution(family, up.points.back().x, {1.2, 1.1, 1.0}, o);
  print(down);
  ASSERT_TRUE(down.finished);
  EXPECT_TRUE(up.jumps.empty());
  EXPECT_TRUE(down.jumps.empty());
  const CurvePoint& back = down.points.back();
  EXPECT_DOUBLE_EQ(back.parameter, 1.0);
  EXPECT_NEAR(back.objective, up.points.front().objective, 1e-6 * std::abs(up.points.front().objective));
  EXPECT_LT((back.x - up.points.front().x).lpNorm<Eigen::Infinity>(), 1e-3);
  for (const CurvePoint& p : up.points) EXPECT_TRUE(p.converged);
}
