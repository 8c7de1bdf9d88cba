// The seed's method on the single giant swing (seed 000, ch. 5.1; issue acceptance 2), the
// evaluation functions (eq. 4.9, 4.14) and the one-step Jacobian of the open-loop swing against
// finite differences.
#include "cyclopt/giant_swing/evaluation.hpp"
#include "cyclopt/giant_swing/one_step_map.hpp"
#include "cyclopt/giant_swing/seed_optimiser.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace cyclopt::giant_swing {
namespace {

const Model kModel = appendix_b_gymnast();

TaskSpec single_swing_task() {
  TaskSpec spec = default_task(TaskKind::single_swing);
  spec.optimiser.support_points = 4;
  spec.optimiser.max_support_points = 8;
  spec.optimiser.max_evaluations_per_run = 1000;
  spec.optimiser.max_evaluations = 4000;
  spec.optimiser.min_step = 2.5;
  return spec;
}

// One optimisation shared by the tests below.
const SeedMethodResult& seed_result() {
  static const SeedMethodResult r = optimise_seed_method(kModel, single_swing_task());
  return r;
}

SimulationOptions tight_options() {
  SimulationOptions o = simulation_options(single_swing_task());
  o.integrator.relative_tolerance = 1e-12;
  o.integrator.absolute_tolerance = 1e-14;
  return o;
}

TEST(SeedMethod, WithoutHipTorqueFrictionStopsTheSwing) {
  const TaskSpec spec = single_swing_task();
  const TaskEvaluation e = evaluate_task(kModel, spec, HipTorqueProfile{Eigen::VectorXd::Zero(4)});
  ASSERT_TRUE(e.simulation.failed);
  std::printf("zero torque: fails at phi = %.1f deg (%s), score %.1f (eq. 4.9)\n", e.simulation.failure_phi * kDegPerRad,
              e.simulation.failure_reason.c_str(), e.score);
  EXPECT_NEAR(e.score, failed_swing_score(e.simulation.failure_phi), 1e-9);
  EXPECT_GT(e.score, 1000.0);
}

TEST(SeedMethod, NelderMeadFindsAClosedGiantSwing) {
  const SeedMethodResult& seed = seed_result();
  const TaskSpec spec = single_swing_task();
  ASSERT_FALSE(seed.best.simulation.failed) << seed.best.simulation.failure_reason;
  const RoundResult& r = seed.best.simulation.rounds[0];
  std::printf("seed method (%d integrations, %.2f s, %ld support points): phi'/omega = %.6f, alpha = %.3e deg, "
              "alpha' = %.3f deg/s, friction %.2f J, jerk %.1f, moment %.1f; score %.3f\n",
              seed.integrations, seed.wall_seconds, long(seed.torque.support_values.size()), r.phi_rate / spec.omega,
              r.alpha * kDegPerRad, r.alpha_rate * kDegPerRad, r.friction_loss, r.jerk, r.torque_integral,
              seed.best.score);
  EXPECT_NEAR(r.phi_rate / spec.omega, 1.0, 2e-3);
  EXPECT_LT(std::abs(r.alpha) * kDegPerRad, 0.05);
  // alpha' is the slow term for Nelder-Mead in 4-8 dimensions (bench/giant_swing_bench runs longer).
  EXPECT_LT(std::abs(r.alpha_rate) * kDegPerRad, 60.0);
  // The friction loss is the seed's 58-63 J (tables of ch. 5.1).
  EXPECT_GT(r.friction_loss, 50.0);
  EXPECT_LT(r.friction_loss, 75.0);
}

TEST(SeedMethod, OneStepJacobianAgreesWithFiniteDifferences) {
  // The open-loop swing of the seed's method: its one-step map is strongly unstable, which is why
  // the seed's sequences break off after a few swings (ch. 5.2).
  const SectionState handstand(kReferenceRate, 0.0, 0.0);
  const PiecewiseLinearTorque law(seed_result().torque);
  const SimulationOptions o = tight_options();
  const OneStepJacobian exact = one_step_jacobian(kModel, law, handstand, o);
  ASSERT_TRUE(exact.ok);
  const Eigen::Matrix3d fd = one_step_jacobian_by_differences(kModel, law, handstand, o);
  const double rel = (exact.jacobian - fd).norm() / fd.norm();
  const Eigen::Vector3cd lam = floquet_multipliers(exact.jacobian), lam_fd = floquet_multipliers(fd);
  std::printf("seed swing one-step Jacobian: variational vs central differences, relative difference %.2e\n", rel);
  for (int i = 0; i < 3; ++i)
    std::printf("  eigenvalue %d: %+.6f %+.6fi   finite differences: %+.6f %+.6fi\n", i, lam[i].real(), lam[i].imag(),
                lam_fd[i].real(), lam_fd[i].imag());
  EXPECT_LT(rel, 1e-5);
  const double radius = lam.cwiseAbs().maxCoeff();
  EXPECT_NEAR(radius, lam_fd.cwiseAbs().maxCoeff(), 1e-5 * radius);
  EXPECT_GT(radius, 1.0);
}

TEST(Evaluation, SequenceScoreRewardsCompletedRounds) {
  // eq. 4.14: (sum F_n) 10^(20 - 3 R).
  SimulationResult s;
  RoundResult exact;
  exact.phi_rate = kReferenceRate;
  RoundResult off = exact;
  off.alpha = 1.0 / kDegPerRad;  // 1 degree: F = 10
  s.rounds = {off, exact};
  s.failed = true;
  s.failure_phi = 2 * kTwoPi + 1.0;
  EXPECT_NEAR(evaluation_score(EvaluationWeights{}, s, 10, kReferenceRate), 10.0 * 1e14, 1e3);
  s.rounds.clear();
  s.failure_phi = 1.0;
  EXPECT_NEAR(evaluation_score(EvaluationWeights{}, s, 10, kReferenceRate), 1000.0 * (1.0 + kTwoPi - 1.0) * 1e20, 1e8);
  EXPECT_NEAR(evaluation_score(EvaluationWeights{}, s, 1, kReferenceRate), 1000.0 * (1.0 + kTwoPi - 1.0), 1e-9);
}

}  // namespace
}  // namespace cyclopt::giant_swing
