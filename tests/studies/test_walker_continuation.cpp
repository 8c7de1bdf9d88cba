// The QPSQP continuation (seed 001, Algorithm 2) on the point-foot walker over the mean speed,
// and the sensitivity study of section 10.1 over a model parameter.
#include "cyclopt/continuation/continuation_solver.hpp"
#include "cyclopt/studies/sensitivity.hpp"
#include "cyclopt/studies/walker_family.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"

#include <gtest/gtest.h>

#include <cstdio>

using namespace cyclopt;
using namespace cyclopt::continuation;
using namespace cyclopt::studies;

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

TEST(WalkerContinuation, SensitivityFollowsTheOptimumOverAModelParameter) {
  const PointFeet& pf = point_feet();
  ASSERT_TRUE(pf.start.summary.success());
  SensitivityOptions o;
  o.parameters = {"m_T"};  // torso mass
  o.relative_range = 0.04;
  o.steps = 1;
  const std::vector<SensitivityCurve> s = sensitivity(pf.model, pf.problem, pf.start.z, o);
  ASSERT_EQ(s.size(), 1u);
  for (const SensitivityPoint& p : s[0].points)
    std::printf("m_T %+.3f: delta f %+.6f (curve %d)\n", p.relative_change, p.delta_objective, p.curve_id);
  ASSERT_EQ(s[0].points.size(), 3u) << s[0].message;
  EXPECT_EQ(s[0].jumps, 0);
  EXPECT_DOUBLE_EQ(s[0].points[1].relative_change, 0.0);
  EXPECT_NEAR(s[0].points[1].delta_objective, 0.0, 1e-12);
  for (const SensitivityPoint& p : s[0].points) EXPECT_EQ(p.curve_id, 0);
}
