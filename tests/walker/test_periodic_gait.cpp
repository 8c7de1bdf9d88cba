// The semi-analytic periodic gait (seed 001 eq. 5.76-5.97) against an independent time-domain
// simulation of the full closed-loop model (forward_simulation.hpp): return to the same post-impact
// state, step period, cost of transport, Floquet multiplier as the slope of the Poincare map, and
// the energy balance of a step.
#include "reference_gaits.hpp"

#include "cyclopt/walker/forward_simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace cyclopt::walker {
namespace {

using testing::kReferenceFeet;

constexpr int kFinePoints = 12800;

struct FineGait {
  WalkerModel<double> model;
  PeriodicGait<double> gait;
};

// The reference starting gait re-evaluated on a fine grid, where the quadrature error is ~1e-8.
FineGait fine_gait(const char* foot) {
  const auto& ref = testing::reference_gait(foot);
  EXPECT_TRUE(ref.start.feasible) << foot << ": " << ref.start.message;
  FineGait f{testing::reference_model(foot, kFinePoints), {}};
  f.gait = GaitEvaluator(f.model).evaluate(ref.start.x, GaitOptions{Objective::mechanical, 1.3, true});
  EXPECT_TRUE(f.gait.real) << f.gait.failure;
  return f;
}

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

TEST(PeriodicGait, ForwardSimulationReturnsToTheSamePostImpactState) {
  for (const char* foot : kReferenceFeet) {
    const FineGait f = fine_gait(foot);
    const auto& tr = f.gait.trajectory;
    const Eigen::VectorXd q0 = tr.q.col(0), qd0 = tr.q_dot.col(0);
    const StepSimulation s = simulate_step(f.model, f.gait.constraints, q0, qd0, SimulationOptions{});
    ASSERT_TRUE(s.landed) << foot << ": " << s.failure;
    const double dq = (s.q_plus - q0).norm() / q0.norm(), dqd = (s.q_dot_plus - qd0).norm() / qd0.norm();
    const double W = f.model.total_mass * f.model.constants.gravity * s.step_length;
    std::printf("%s (P = %d): post-impact q %.2e, q_dot %.2e rel.; period %.10f vs %.10f s; f_mech %.10f vs %.10f; "
                "%d steps, %d rhs calls\n", foot, kFinePoints, dq, dqd, s.step_period, f.gait.step_period,
                s.mechanical_energy / W, f.gait.f_mech, s.integration.steps, s.integration.evaluations);
    EXPECT_LE(dq, 1e-6) << foot;
    EXPECT_LE(dqd, 1e-6) << foot;
    EXPECT_LE(relative(s.step_period, f.gait.step_period), 1e-6) << foot;
    EXPECT_LE(relative(s.step_length, f.gait.step_length), 1e-9) << foot;
    EXPECT_LE(relative(s.mechanical_energy / W, f.gait.f_mech), 1e-6) << foot;
    EXPECT_LE(relative(s.squared_torque / W, f.gait.f_usq), 1e-6) << foot;
  }
}

// zeta = sigma^2 / 2 with sigma = dL/d theta_dot = (M_s q_dot)_0 (eq. 5.37, 5.75).
double zeta(const WalkerModel<double>& m, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
  const StanceFrame<double> f = stance_frame(m, CoordinateVector<double>(q));
  const double sigma = (mass_matrix(m, f) * qd)(0);
  return 0.5 * sigma * sigma;
}

TEST(PeriodicGait, FloquetMultiplierIsTheSlopeOfTheSimulatedPoincareMap) {
  for (const char* foot : kReferenceFeet) {
    const FineGait f = fine_gait(foot);
    const auto& tr = f.gait.trajectory;
    const Eigen::VectorXd q0 = tr.q.col(0), qd0 = tr.q_dot.col(0);
    const double z0 = zeta(f.model, q0, qd0), eps = 1e-3;
    double z_next[2];
    for (int k = 0; k < 2; ++k) {
      const double scale = std::sqrt(1.0 + (k == 0 ? eps : -eps));  // zeta+ -> zeta+ (1 +- eps), on the manifold
      const StepSimulation s = simulate_step(f.model, f.gait.constraints, q0, scale * qd0, SimulationOptions{});
      ASSERT_TRUE(s.landed) << foot << ": " << s.failure;
      z_next[k] = zeta(f.model, s.q_plus, s.q_dot_plus);
    }
    const double slope = (z_next[0] - z_next[1]) / (2.0 * eps * z0);
    std::printf("%s: Poincare slope from simulation %.8f, Lambda (5.89) %.8f\n", foot, slope, f.gait.floquet);
    EXPECT_NEAR(slope, f.gait.floquet, 1e-5 * std::abs(f.gait.floquet)) << foot;
  }
}

TEST(PeriodicGait, ActuatorWorkOverAStepEqualsTheImpactLoss) {
  for (const char* foot : kReferenceFeet) {
    const FineGait f = fine_gait(foot);
    const auto& tr = f.gait.trajectory;
    // Signed actuator work of the semi-analytic gait, trapezoid in time over the grid.
    // The scale is the gross work int sum |u_i q_b_dot_i| dt, of which the net work is a small difference.
    double work = 0.0, gross = 0.0;
    const int nb = f.model.joint_count;
    for (int i = 0; i + 1 < tr.time.size(); ++i) {
      const Eigen::ArrayXd p0 = tr.torque.col(i).array() * tr.q_dot.col(i).tail(nb).array();
      const Eigen::ArrayXd p1 = tr.torque.col(i + 1).array() * tr.q_dot.col(i + 1).tail(nb).array();
      const double dt = tr.time(i + 1) - tr.time(i);
      work += 0.5 * (p0.sum() + p1.sum()) * dt;
      gross += 0.5 * (p0.abs().sum() + p1.abs().sum()) * dt;
    }
    const StepSimulation s = simulate_step(f.model, f.gait.constraints, tr.q.col(0), tr.q_dot.col(0), SimulationOptions{});
    ASSERT_TRUE(s.landed) << foot;
    std::printf("%s: work %.9f J (semi-analytic), %.9f J (simulated), impact loss %.9f J, gross work %.3f J; "
                "simulated W - dE = %.2e J\n", foot, work, s.actuator_work, f.gait.impact_energy_loss, gross,
                s.actuator_work - s.energy_change);
    EXPECT_LE(std::abs(work - f.gait.impact_energy_loss), 1e-6 * gross) << foot;
    EXPECT_LE(std::abs(s.actuator_work - s.impact_energy_loss), 1e-6 * gross) << foot;
    EXPECT_LE(std::abs(s.actuator_work - s.energy_change), 1e-8 * gross) << foot;
  }
}

TEST(PeriodicGait, QuadratureErrorFallsWithTheSquareOfTheGridSpacing) {
  const auto& ref = testing::reference_gait("P1-barefoot-left-HM");
  const GaitOptions opt{Objective::mechanical, 1.3, false};
  const double T_fine = GaitEvaluator(testing::reference_model("P1-barefoot-left-HM", 4 * kFinePoints))
                            .evaluate(ref.start.x, opt).step_period;
  double err[2];
  int k = 0;
  for (int P : {400, 1600}) err[k++] = std::abs(GaitEvaluator(testing::reference_model("P1-barefoot-left-HM", P))
                                                    .evaluate(ref.start.x, opt).step_period - T_fine);
  std::printf("period error P=400: %.3e, P=1600: %.3e (ratio %.1f, trapezoid rule: 16)\n", err[0], err[1], err[0] / err[1]);
  EXPECT_GT(err[0] / err[1], 12.0);
  EXPECT_LT(err[0] / err[1], 20.0);
}

}  // namespace
}  // namespace cyclopt::walker

namespace cyclopt::walker {
namespace {

TEST(Quadrature, CorrectedTrapezoidIsFourthOrderOnEveryRunningIntegral) {
  double err[2];
  int k = 0;
  for (int P : {101, 201}) {
    const double h = 2.0 / (P - 1);
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(P, 0.0, 2.0);
    const Eigen::VectorXd I = cumulative_integral(Eigen::VectorXd(x.array().exp()), h, Quadrature::corrected_trapezoid);
    err[k++] = (I.array() - (x.array().exp() - 1.0)).abs().maxCoeff();
  }
  std::printf("corrected trapezoid on exp: max error %.2e (P=101), %.2e (P=201), ratio %.1f\n", err[0], err[1],
              err[0] / err[1]);
  EXPECT_GT(err[0] / err[1], 14.0);
  EXPECT_LT(err[1], 5e-9);
}

TEST(Quadrature, CorrectedRuleConvergesFasterOnTheGait) {
  const auto& ref = testing::reference_gait("P2-shoes-left-HMT");
  GaitOptions opt{Objective::mechanical, 1.3, false};
  opt.quadrature = Quadrature::corrected_trapezoid;
  const PeriodicGait<double> fine = GaitEvaluator(testing::reference_model("P2-shoes-left-HMT", 25600)).evaluate(ref.start.x, opt);
  const GaitEvaluator ev(testing::reference_model("P2-shoes-left-HMT", 1600));
  const PeriodicGait<double> corrected = ev.evaluate(ref.start.x, opt);
  opt.quadrature = Quadrature::trapezoid;
  const PeriodicGait<double> trapezoid = ev.evaluate(ref.start.x, opt);
  const double e_c = std::abs(corrected.floquet - fine.floquet), e_t = std::abs(trapezoid.floquet - fine.floquet);
  std::printf("Lambda error at P = 1600: trapezoid %.2e, corrected %.2e\n", e_t, e_c);
  EXPECT_LT(e_c, 1e-2 * e_t);
  // f_mech (the positive-part rule) at the sweeps' P = 200: 2.6e-6 against 1.6e-3 relative (docs/walker-jobs.md).
  const GaitEvaluator coarse(testing::reference_model("P2-shoes-left-HMT", 200));
  const double f_t = coarse.evaluate(ref.start.x, opt).f_mech;
  opt.quadrature = Quadrature::corrected_trapezoid;
  const double f_c = coarse.evaluate(ref.start.x, opt).f_mech;
  const double m_t = std::abs(f_t - fine.f_mech) / fine.f_mech, m_c = std::abs(f_c - fine.f_mech) / fine.f_mech;
  std::printf("f_mech relative error at P = 200: trapezoid %.2e, corrected %.2e\n", m_t, m_c);
  EXPECT_LT(m_c, 1e-5);
  EXPECT_LT(m_c, 1e-2 * m_t);
}

// f_mech's integrand max(p, 0): sin(3x) + 0.3 on [0, 2] changes sign four times. Exact integral
// of the positive part from the closed-form roots; the seed's rule is second order, the new one fourth.
TEST(Quadrature, PositivePartRuleIsFourthOrderAcrossSignChanges) {
  const auto g = [](double x) { return std::sin(3.0 * x) + 0.3; };
  const auto G = [](double x) { return -std::cos(3.0 * x) / 3.0 + 0.3 * x; };  // antiderivative
  const double r = std::asin(0.3), pi = std::numbers::pi;
  // g > 0 on [0, (pi + r)/3) and ((2 pi - r)/3, 2]: (3 pi + r)/3 = 3.24 > 2.
  const double exact = G((pi + r) / 3.0) - G(0.0) + G(2.0) - G((2.0 * pi - r) / 3.0);
  double err[2], err_seed[2];
  int k = 0;
  for (int P : {101, 201}) {
    const double h = 2.0 / (P - 1);
    Eigen::VectorXd f(P);
    for (int i = 0; i < P; ++i) f(i) = g(i * h);
    err[k] = std::abs(positive_part_integral(f, h) - exact);
    double seed = 0.0;
    for (int i = 0; i + 1 < P; ++i) seed += positive_part_trapezoid(f(i), f(i + 1), h);
    err_seed[k++] = std::abs(seed - exact);
  }
  std::printf("positive part of sin(3x) + 0.3: error %.2e / %.2e (P = 101 / 201, ratio %.1f); seed's rule %.2e / %.2e\n",
              err[0], err[1], err[0] / err[1], err_seed[0], err_seed[1]);
  EXPECT_GT(err[0] / err[1], 12.0);
  EXPECT_LT(err[1], 1e-2 * err_seed[1]);
}

// The rule's derivative with respect to the samples (Dual) against central differences of its value.
TEST(Quadrature, PositivePartRuleHasExactSampleDerivatives) {
  const int P = 41;
  const double h = 0.05;
  Eigen::VectorXd f(P);
  for (int i = 0; i < P; ++i) f(i) = std::sin(3.0 * i * h) + 0.3;
  using D = ad::Dual<1>;
  for (int j : {0, 5, 20, 21, 33, 40}) {  // 21 and 33 lie next to sign changes
    Eigen::Matrix<D, Eigen::Dynamic, 1> fd(P);
    for (int i = 0; i < P; ++i) fd(i) = D(f(i));
    fd(j).d[0] = 1.0;
    const double exact = positive_part_integral(fd, D(h)).d[0];
    const double step = 1e-6;
    Eigen::VectorXd up = f, down = f;
    up(j) += step;
    down(j) -= step;
    const double diff = (positive_part_integral(up, h) - positive_part_integral(down, h)) / (2.0 * step);
    EXPECT_NEAR(exact, diff, 1e-7) << "sample " << j;
  }
}

}  // namespace
}  // namespace cyclopt::walker
