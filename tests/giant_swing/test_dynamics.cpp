// Equations of motion of the gymnast (seed 000, ch. 3, appendix A) checked by independent means:
// energy conservation of the free double pendulum, the energy and angular-momentum balances
// (3.4-3.5, A.64) along integrated trajectories with friction and hip torque, the seed's own
// matrix form (3.2), the implicit friction law (A.69), and Dual against complex-step derivatives.
#include "cyclopt/giant_swing/energy_momentum.hpp"
#include "cyclopt/giant_swing/hip_torque.hpp"
#include "cyclopt/ode/cash_karp.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <cstdio>

namespace cyclopt::giant_swing {
namespace {

const HipTorqueProfile kSomeTorque{(Eigen::VectorXd(8) << 40.0, -60.0, 120.0, 80.0, -30.0, -150.0, 20.0, 90.0).finished()};

ode::CashKarpOptions tight() {
  ode::CashKarpOptions o;
  o.relative_tolerance = 1e-13;
  o.absolute_tolerance = 1e-15;
  return o;
}

TEST(GiantSwingDynamics, FreeDoublePendulumConservesEnergy) {
  Model model = appendix_b_gymnast();
  model.friction_coefficient = 0.0;
  const State<double> x0(0.0, 0.0, kReferenceRate, 0.0);
  const double E0 = total_energy(model, x0);
  double worst = 0.0;
  auto rhs = [&](double, const State<double>& x) { return state_derivative(model, x, 0.0); };
  auto observe = [&](double, const State<double>& x) {
    worst = std::max(worst, std::abs(total_energy(model, x) - E0) / std::abs(E0));
  };
  // One swing of the passive pendulum takes about 2.5 s; integrate 4 s.
  const auto r = ode::integrate(rhs, 0.0, x0, 4.0, tight(), ode::NoEvents{}, observe);
  ASSERT_EQ(r.status, ode::IntegrationStatus::reached_end);
  std::printf("free pendulum: max relative energy drift %.3e over 4 s (%d steps), phi(4 s) = %.3f rad\n", worst,
              r.stats.accepted_steps, r.y[0]);
  EXPECT_LT(worst, 1e-9);
}

// Integrates x together with int (M_R phi' + M_alpha alpha') dt and int (M_R + M_G) dt.
struct Balances {
  double energy_error = 0.0;    // max |E - E0 - W| / max |E|
  double momentum_error = 0.0;  // max |L - L0 - int M_ext| / max |L|
  double friction_work = 0.0;
};

Balances check_balances(const Model& model, const HipTorqueProfile& torque, double duration) {
  using Y = Eigen::Matrix<double, 6, 1>;
  auto rhs = [&](double, const Y& y) {
    const State<double> x = y.head<4>();
    const double M = hip_torque(torque, x[0]);
    const Accelerations<double> a = accelerations(model, x, M);
    Y dy;
    dy << x[2], x[3], a.qdd[0], a.qdd[1], a.friction_moment * x[2] + M * x[3],
        a.friction_moment + gravity_moment(model, x);
    return dy;
  };
  Y y0 = Y::Zero();
  y0.head<4>() = State<double>(0.0, 0.0, kReferenceRate, 0.0);
  const double E0 = total_energy(model, State<double>(y0.head<4>())), L0 = angular_momentum(model, State<double>(y0.head<4>()));
  double e_err = 0.0, l_err = 0.0, e_max = 0.0, l_max = 0.0;
  Balances b;
  auto observe = [&](double, const Y& y) {
    const State<double> x = y.head<4>();
    e_max = std::max(e_max, std::abs(total_energy(model, x)));
    l_max = std::max(l_max, std::abs(angular_momentum(model, x)));
    e_err = std::max(e_err, std::abs(total_energy(model, x) - E0 - y[4]));
    l_err = std::max(l_err, std::abs(angular_momentum(model, x) - L0 - y[5]));
  };
  const auto r = ode::integrate(rhs, 0.0, y0, duration, tight(), ode::NoEvents{}, observe);
  EXPECT_EQ(r.status, ode::IntegrationStatus::reached_end);
  b.energy_error = e_err / e_max;
  b.momentum_error = l_err / l_max;
  return b;
}

TEST(GiantSwingDynamics, EnergyAndAngularMomentumBalancesHoldWithFrictionAndTorque) {
  const Balances b = check_balances(appendix_b_gymnast(), kSomeTorque, 3.0);
  std::printf("with friction and hip torque over 3 s: energy balance error %.3e, momentum balance (3.5) error %.3e\n",
              b.energy_error, b.momentum_error);
  EXPECT_LT(b.energy_error, 1e-10);
  EXPECT_LT(b.momentum_error, 1e-10);
}

TEST(GiantSwingDynamics, SatisfiesTheSeedsMatrixForm) {
  // Seed 000 eq. (3.2): the non-symmetric rows (A.57) and (A.58).
  const Model model = appendix_b_gymnast();
  const InertiaConstants c = inertia_constants(model);
  for (const State<double>& x : {State<double>(0.3, 0.2, 1.5, -0.7), State<double>(2.8, -0.5, 4.0, 2.0),
                                 State<double>(5.5, 1.2, 0.4, 0.1)}) {
    const double M_alpha = 57.0;
    const Accelerations<double> a = accelerations(model, x, M_alpha);
    const double phi = x[0], al = x[1], pd = x[2], ad = x[3], pdd = a.qdd[0], add = a.qdd[1];
    const double row1 = (c.Theta1 + c.chi1 * std::cos(al)) * pdd + c.chi1 * std::cos(al) * add -
                        (a.friction_moment - M_alpha + c.chi2 * model.g * std::sin(phi) +
                         c.chi1 * std::sin(al) * (pd + ad) * (pd + ad));
    const double row2 = (c.Theta2 + c.chi1 * std::cos(al)) * pdd + c.Theta2 * add -
                        (M_alpha - c.chi1 * std::sin(al) * pd * pd + c.chi3 * model.g * std::sin(phi + al));
    EXPECT_NEAR(row1, 0.0, 1e-10);
    EXPECT_NEAR(row2, 0.0, 1e-10);
    // (3.9) recovers the hip torque from the motion.
    EXPECT_NEAR(hip_torque_for(model, x, a.qdd), M_alpha, 1e-10);
    // Friction (A.69): M_R = -r mu |F| with F from the accelerations it produced.
    EXPECT_NEAR(a.friction_moment, -model.bar_radius * model.friction_coefficient * bar_normal_force(model, x, a.qdd),
                1e-12);
    EXPECT_LT(a.friction_moment, 0.0);
  }
}

TEST(GiantSwingDynamics, DualDerivativesMatchComplexStep) {
  const Model model = appendix_b_gymnast();
  const State<double> x(1.1, 0.4, 2.5, -1.0);
  using D = ad::Dual<4>;
  State<D> xd;
  for (int i = 0; i < 4; ++i) xd[i] = D::variable(x[i], i);
  const State<D> fd = state_derivative(model, xd, hip_torque(kSomeTorque, xd[0]));
  const double h = 1e-30;
  for (int j = 0; j < 4; ++j) {
    State<std::complex<double>> xc = x.cast<std::complex<double>>();
    xc[j] += std::complex<double>(0.0, h);
    const State<std::complex<double>> fc =
        state_derivative(model, xc, std::complex<double>(hip_torque(kSomeTorque, x[0])) +
                                        (j == 0 ? std::complex<double>(0.0, h) *
                                                      ((kSomeTorque.support_values[2] - kSomeTorque.support_values[1]) *
                                                       8.0 / kTwoPi)
                                                : 0.0));
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(fd[i].d[j], fc[i].imag() / h, 1e-9 * (1.0 + std::abs(fd[i].d[j])));
  }
}

TEST(GiantSwingDynamics, RefinedTorqueIsTheSameFunction) {
  const HipTorqueProfile fine = refined(kSomeTorque);
  ASSERT_EQ(fine.support_values.size(), 16);
  for (double phi = -1.0; phi < 14.0; phi += 0.0137)
    EXPECT_NEAR(hip_torque(fine, phi), hip_torque(kSomeTorque, phi), 1e-12);
  EXPECT_NEAR(hip_torque(kSomeTorque, kTwoPi), kSomeTorque.support_values[0], 1e-12);  // periodic
}

}  // namespace
}  // namespace cyclopt::giant_swing
