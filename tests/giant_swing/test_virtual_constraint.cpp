// Part B: the hip angle as a virtual constraint alpha = b(phi) (Bezier), enforced by the hip torque
// of eq. 3.9 with PD error feedback. A closed giant swing from the handstand, its Floquet
// multipliers against a finite-difference one-step map, and a periodic sequence of 12 swings
// (issue acceptance 2 and 4).
#include "cyclopt/giant_swing/minimum_jerk_problem.hpp"
#include "cyclopt/giant_swing/one_step_map.hpp"
#include "cyclopt/giant_swing/virtual_constraint.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace cyclopt::giant_swing {
namespace {

const Model kModel = appendix_b_gymnast();
constexpr double kKp = 400.0, kKd = 40.0;  // 1/s^2, 1/s: error dynamics with a double pole at -20/s
const SectionState kHandstand(kReferenceRate, 0.0, 0.0);

SimulationOptions tight_options() {
  SimulationOptions o;
  o.integrator.relative_tolerance = 1e-12;
  o.integrator.absolute_tolerance = 1e-14;
  return o;
}

// Pike after the lowest point: free coefficients a (0, 0, 1, 1).
VirtualConstraintTorque law_for(double a) {
  return VirtualConstraintTorque(bezier_from_free(Eigen::Vector4d(0.0, 0.0, a, a)), kKp, kKd, kModel);
}

// The amplitude a for which phi' returns to omega after one swing (Newton on the zero dynamics).
double amplitude() {
  static const double a = [] {
    MinimumJerkProblem problem(kModel, default_task(TaskKind::single_swing), {4, 400});
    const auto x = scale_to_close(problem, Eigen::Vector4d(0.0, 0.0, 1.0, 1.0), 1.2);
    return x ? (*x)[2] : 0.0;
  }();
  return a;
}

TEST(VirtualConstraint, BezierDerivativesMatchDifferences) {
  const BezierCoefficients<double> c = bezier_from_free(Eigen::Vector4d(0.3, -0.2, 0.8, 0.5));
  for (double phi : {0.4, 2.0, 3.5, 5.9}) {
    const auto b = bezier_hip_angle<double>(c, phi);
    const double h = 1e-5;
    for (int k = 0; k < 3; ++k) {
      const double numeric =
          (bezier_hip_angle<double>(c, phi + h)[k] - bezier_hip_angle<double>(c, phi - h)[k]) / (2.0 * h);
      EXPECT_NEAR(b[k + 1], numeric, 1e-6 * (1.0 + std::abs(numeric)));
    }
  }
  for (double phi : {0.0, kTwoPi}) {  // handstand: alpha = alpha' = alpha'' = 0 (eq. 3.10-3.11)
    const auto b = bezier_hip_angle<double>(c, phi);
    EXPECT_NEAR(b[0], 0.0, 1e-15);
    EXPECT_NEAR(b[1], 0.0, 1e-15);
    EXPECT_NEAR(b[2], 0.0, 1e-15);
  }
}

TEST(VirtualConstraint, ClosedGiantSwingReturnsToTheHandstand) {
  const OneStep step = one_step_map(kModel, law_for(amplitude()), kHandstand, tight_options());
  ASSERT_TRUE(step.ok);
  std::printf("virtual constraint a = %.12f: phi'/omega - 1 = %.2e, alpha = %.2e deg, alpha' = %.2e deg/s; "
              "friction %.2f J, jerk %.2f, moment %.1f, %.3f s\n",
              amplitude(), step.next[0] / kReferenceRate - 1.0, step.next[1] * kDegPerRad, step.next[2] * kDegPerRad,
              step.round.friction_loss, step.round.jerk, step.round.torque_integral, step.round.duration);
  EXPECT_NEAR(step.next[0] / kReferenceRate, 1.0, 1e-10);
  EXPECT_NEAR(step.next[1], 0.0, 1e-9);
  EXPECT_NEAR(step.next[2], 0.0, 1e-9);
  EXPECT_GT(step.round.friction_loss, 50.0);
}

TEST(VirtualConstraint, FloquetMultipliersAgreeWithFiniteDifferences) {
  const VirtualConstraintTorque law = law_for(amplitude());
  const OneStepJacobian exact = one_step_jacobian(kModel, law, kHandstand, tight_options());
  ASSERT_TRUE(exact.ok);
  const Eigen::Matrix3d fd = one_step_jacobian_by_differences(kModel, law, kHandstand, tight_options());
  const double rel = (exact.jacobian - fd).norm() / fd.norm();
  const Eigen::Vector3cd lam = floquet_multipliers(exact.jacobian), lam_fd = floquet_multipliers(fd);
  std::printf("closed-loop one-step Jacobian: variational vs central differences, relative difference %.2e\n", rel);
  for (int i = 0; i < 3; ++i)
    std::printf("  multiplier %d: %+.8f %+.8fi (|.| = %.8f)   finite differences: %+.8f %+.8fi\n", i, lam[i].real(),
                lam[i].imag(), std::abs(lam[i]), lam_fd[i].real(), lam_fd[i].imag());
  EXPECT_LT(rel, 1e-6);
  const double radius = lam.cwiseAbs().maxCoeff();
  EXPECT_NEAR(radius, lam_fd.cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT(radius, 1.0);  // the sequence is stable
}

TEST(VirtualConstraint, PeriodicSequenceOfTwelveSwingsStaysAdmissible) {
  // Start slightly off the periodic orbit (0.5 deg/s faster, 1 deg bent) to show it is attracting.
  const State<double> x0(0.0, 1.0 / kDegPerRad, kReferenceRate + 0.5 / kDegPerRad, 0.0);
  double alpha_min = 0.0, alpha_max = 0.0, rate_min = 1e9;
  const SimulationResult r =
      simulate_swings(kModel, law_for(amplitude()), x0, 12, tight_options(), [&](double, const AugmentedState& y) {
        alpha_min = std::min(alpha_min, y[1]);
        alpha_max = std::max(alpha_max, y[1]);
        rate_min = std::min(rate_min, y[2]);
      });
  ASSERT_FALSE(r.failed) << "after " << r.rounds.size() << " swings: " << r.failure_reason;
  ASSERT_EQ(r.rounds.size(), 12u);
  for (std::size_t n = 0; n < r.rounds.size(); ++n)
    std::printf("  swing %2zu: phi'/omega - 1 = %+.3e, alpha = %+.3e deg, alpha' = %+.3e deg/s\n", n + 1,
                r.rounds[n].phi_rate / kReferenceRate - 1.0, r.rounds[n].alpha * kDegPerRad,
                r.rounds[n].alpha_rate * kDegPerRad);
  std::printf("12 swings: alpha in [%.2f, %.2f] deg, min phi' = %.3f rad/s\n", alpha_min * kDegPerRad,
              alpha_max * kDegPerRad, rate_min);
  const RoundResult& last = r.rounds.back();
  EXPECT_LT(std::abs(last.phi_rate / kReferenceRate - 1.0), std::abs(0.5 / kDegPerRad / kReferenceRate));
  EXPECT_GT(alpha_min, -std::numbers::pi / 4.0);
  EXPECT_LT(alpha_max, std::numbers::pi / 2.0);
  EXPECT_GT(rate_min, 0.0);
}

}  // namespace
}  // namespace cyclopt::giant_swing
