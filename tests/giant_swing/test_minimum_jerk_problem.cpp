// Part B groundwork: the zero dynamics on alpha = b(phi) agree with the full model driven by the
// virtual-constraint torque law (an independent integration in time with event location), and the
// minimum-jerk NLP's exact derivatives agree with central differences.
#include "cyclopt/giant_swing/closed_swing_search.hpp"
#include "cyclopt/giant_swing/minimum_jerk_problem.hpp"
#include "cyclopt/giant_swing/one_step_map.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace cyclopt::giant_swing {
namespace {

const Model kModel = appendix_b_gymnast();
const Eigen::Vector4d kPike(0.0, 0.0, 1.2, 1.2);  // near the closed swing of test_virtual_constraint

TEST(ZeroDynamics, AgreesWithTheFullModelOnTheConstraint) {
  const TaskSpec spec = default_task(TaskKind::single_swing);
  const MinimumJerkProblem problem(kModel, spec, 400);
  const ReducedSwing<double> reduced = problem.swing(kPike);
  ASSERT_TRUE(reduced.ok);
  SimulationOptions o;
  o.integrator.relative_tolerance = 1e-12;
  o.integrator.absolute_tolerance = 1e-14;
  const VirtualConstraintTorque law(bezier_from_free<double>(kPike), 400.0, 40.0, kModel);
  const OneStep full = one_step_map(kModel, law, SectionState(spec.initial_rate, 0.0, 0.0), o);
  ASSERT_TRUE(full.ok);
  const double rate = std::sqrt(reduced.end[0]);
  std::printf("reduced vs full model: phi'(2pi) %.12f vs %.12f, time %.10f vs %.10f s, jerk %.6f vs %.6f, "
              "friction %.8f vs %.8f J, moment %.6f vs %.6f\n",
              rate, full.next[0], reduced.end[1], full.round.duration, reduced.end[2], full.round.jerk, reduced.end[3],
              full.round.friction_loss, reduced.end[4], full.round.torque_integral);
  EXPECT_NEAR(rate, full.next[0], 1e-8 * full.next[0]);
  EXPECT_NEAR(reduced.end[1], full.round.duration, 1e-8);
  EXPECT_NEAR(reduced.end[2], full.round.jerk, 1e-5 * full.round.jerk);
  EXPECT_NEAR(reduced.end[3], full.round.friction_loss, 1e-7 * full.round.friction_loss);
  EXPECT_NEAR(reduced.end[4], full.round.torque_integral, 1e-6 * full.round.torque_integral);
}

TEST(MinimumJerkProblem, DerivativesMatchCentralDifferences) {
  for (TaskKind kind : {TaskKind::single_swing, TaskKind::accelerating, TaskKind::decelerating}) {
    MinimumJerkProblem problem(kModel, default_task(kind), 120);
    const Eigen::VectorXd x = kPike + Eigen::Vector4d(0.05, -0.1, 0.1, 0.02);
    nlp::Evaluation exact;
    ASSERT_TRUE(problem.evaluate(x, true, exact).ok);
    double worst = 0.0;
    for (int j = 0; j < problem.num_variables(); ++j) {
      const double h = 1e-6;
      Eigen::VectorXd plus = x, minus = x;
      plus[j] += h;
      minus[j] -= h;
      nlp::Evaluation ep, em;
      ASSERT_TRUE(problem.evaluate(plus, false, ep).ok);
      ASSERT_TRUE(problem.evaluate(minus, false, em).ok);
      const double g = (ep.objective - em.objective) / (2 * h);
      worst = std::max(worst, std::abs(g - exact.gradient[j]) / (1.0 + std::abs(g)));
      const Eigen::VectorXd ce = (ep.equalities - em.equalities) / (2 * h);
      const Eigen::VectorXd ci = (ep.inequalities - em.inequalities) / (2 * h);
      worst = std::max(worst, (ce - exact.equality_jacobian.col(j)).cwiseAbs().maxCoeff() / (1.0 + ce.cwiseAbs().maxCoeff()));
      worst = std::max(worst, (ci - exact.inequality_jacobian.col(j)).cwiseAbs().maxCoeff() / (1.0 + ci.cwiseAbs().maxCoeff()));
    }
    std::printf("%s: jerk %.3f, phi'(2pi)/omega - 1 = %+.4f, worst relative derivative mismatch %.2e (%d integrations)\n",
                to_string(kind), exact.objective, exact.equalities[0], worst, problem.integrations());
    EXPECT_LT(worst, 1e-6);
  }
}

TEST(MinimumJerkProblem, ReportsAReversingSwingAsEvaluationFailure) {
  MinimumJerkProblem problem(kModel, default_task(TaskKind::single_swing), 120);
  nlp::Evaluation e;
  EXPECT_FALSE(problem.evaluate(Eigen::Vector4d::Zero(), true, e).ok);  // straight body: friction stops it
  EXPECT_EQ(problem.num_inequalities(), 120);
  EXPECT_EQ(problem.lower_bounds()[0], default_task(TaskKind::single_swing).ranges.alpha_min);
}

TEST(ClosedSwingSearch, EveryTrialIsClosedAndJerkDecreases) {
  MinimumJerkProblem problem(kModel, default_task(TaskKind::single_swing), 120);
  const auto start = scale_to_close(problem, Eigen::Vector4d(0.0, 0.0, 1.0, 1.0), 1.2);
  ASSERT_TRUE(start.has_value());
  nlp::Evaluation e;
  ASSERT_TRUE(problem.evaluate(*start, false, e).ok);
  EXPECT_LT(std::abs(e.equalities[0]), 1e-13);
  const double start_jerk = e.objective;
  nlp::NelderMeadOptions o;
  o.initial_step = 0.3;
  o.max_evaluations = 30;
  const ClosedSwingSearchResult r = minimise_jerk_over_closed_swings(problem, Eigen::Vector4d(0.0, 0.0, 1.0, 1.0), o);
  ASSERT_TRUE(r.ok);
  ASSERT_TRUE(problem.evaluate(r.coefficients, false, e).ok);
  std::printf("closed-swing search: jerk %.2f -> %.2f in %d trials (%d integrations)\n", start_jerk, r.jerk,
              r.search.evaluations, r.integrations);
  EXPECT_LT(std::abs(e.equalities[0]), 1e-13);
  EXPECT_NEAR(e.objective, r.jerk, 1e-9 * r.jerk);
  EXPECT_LT(r.jerk, start_jerk);
}

}  // namespace
}  // namespace cyclopt::giant_swing
