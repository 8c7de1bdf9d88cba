// The walker's mass matrix, generalised forces and impact map against the plain kinematic chain of
// reference_mechanics.hpp (seed 001 eq. 5.3, 5.10, 5.16, 5.26): energies, Lagrange's equations by
// central differences of the reference Lagrangian, momentum balance of the impact.
#include "reference_gaits.hpp"
#include "reference_mechanics.hpp"

#include "cyclopt/walker/impact_map.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

namespace cyclopt::walker {
namespace {

using testing::kReferenceFeet;

Eigen::VectorXd random_configuration(const WalkerModel<double>& m, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  Eigen::VectorXd q(m.coordinate_count());
  q(0) = 3.1 + u(rng);
  q(1) = 3.0 + u(rng);
  q(2) = 3.2 + u(rng);
  q(3) = 0.3 + u(rng);
  q(4) = 0.5 + u(rng);
  if (m.has_feet()) {
    q(5) = -0.9 + u(rng);
    q(6) = -0.9 + u(rng);
  }
  return q;
}

Eigen::VectorXd random_velocity(int n, std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 2.0);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v(i) = g(rng);
  return v;
}

TEST(WalkerModel, ScenesBuildOnlyTheSegmentsTheyNeed) {
  const WalkerModel<double> point = testing::reference_model("point");
  EXPECT_EQ(point.segment_count, 5);
  EXPECT_EQ(point.joint_count, 4);
  EXPECT_EQ(point.slot_count, 5);
  const WalkerModel<double> hm = testing::reference_model("P1-barefoot-left-HM");
  EXPECT_EQ(hm.segment_count, 7);
  EXPECT_EQ(hm.joint_count, 6);
  EXPECT_EQ(hm.slot_count, 8);  // + the rolling stance ankle
  EXPECT_NEAR(point.total_mass, 80.16, 1e-9);  // Table D.1 (footnote 15: 80.16 kg)
  EXPECT_NEAR(hm.total_mass, hm.segments[m_T] + 2 * (hm.segments[m_O] + hm.segments[m_U] + hm.segments[m_F]), 1e-12);
}

TEST(WalkerModel, EnergiesMatchTheExplicitKinematicChain) {
  std::mt19937_64 rng(7);
  for (const char* foot : kReferenceFeet) {
    const WalkerModel<double> m = testing::reference_model(foot);
    double worst = 0.0;
    for (int k = 0; k < 200; ++k) {
      const Eigen::VectorXd q = random_configuration(m, rng), qd = random_velocity(m.coordinate_count(), rng);
      const StanceFrame<double> f = stance_frame(m, CoordinateVector<double>(q));
      const double T = kinetic_energy(m, f, CoordinateVector<double>(qd)), T_ref = testing::kinetic_energy(m, q, qd);
      const double V = potential_energy(m, f), V_ref = testing::potential_energy(m, q);
      worst = std::max({worst, std::abs(T - T_ref) / T_ref, std::abs(V - V_ref) / std::abs(V_ref)});
    }
    std::printf("%s: max relative energy difference over 200 states %.2e\n", foot, worst);
    EXPECT_LE(worst, 1e-12) << foot;
  }
}

// tau = d/dt dL/dq_dot - dL/dq with L from the reference chain, by central differences in the
// velocities (exact: T is quadratic in q_dot), in time along q + t q_dot + t^2/2 q_dd, and in q.
TEST(WalkerModel, GeneralizedForcesSatisfyLagrangesEquations) {
  std::mt19937_64 rng(11);
  for (const char* foot : kReferenceFeet) {
    const WalkerModel<double> m = testing::reference_model(foot);
    const int n = m.coordinate_count();
    double worst = 0.0;
    for (int k = 0; k < 20; ++k) {
      const Eigen::VectorXd q = random_configuration(m, rng), qd = random_velocity(n, rng), qdd = random_velocity(n, rng);
      auto dT_dqd = [&](const Eigen::VectorXd& qq, const Eigen::VectorXd& vv, int i) {
        Eigen::VectorXd e = Eigen::VectorXd::Zero(n);
        e(i) = 1e-3;
        return (testing::kinetic_energy(m, qq, vv + e) - testing::kinetic_energy(m, qq, vv - e)) / 2e-3;
      };
      const double h = 1e-5;
      Eigen::VectorXd tau_ref(n);
      for (int i = 0; i < n; ++i) {
        const double ddt = (dT_dqd(q + h * qd + 0.5 * h * h * qdd, qd + h * qdd, i) -
                            dT_dqd(q - h * qd + 0.5 * h * h * qdd, qd - h * qdd, i)) / (2 * h);
        Eigen::VectorXd e = Eigen::VectorXd::Zero(n);
        e(i) = h;
        const double dL_dq = (testing::kinetic_energy(m, q + e, qd) - testing::potential_energy(m, q + e) -
                              testing::kinetic_energy(m, q - e, qd) + testing::potential_energy(m, q - e)) / (2 * h);
        tau_ref(i) = ddt - dL_dq;
      }
      const StanceFrame<double> f = stance_frame(m, CoordinateVector<double>(q));
      const CoordinateVector<double> tau = generalized_forces(m, f, CoordinateVector<double>(qd), CoordinateVector<double>(qdd));
      worst = std::max(worst, (tau - tau_ref).cwiseAbs().maxCoeff() / tau_ref.cwiseAbs().maxCoeff());
    }
    std::printf("%s: max relative difference of M q_dd + Gamma from Lagrange by differences %.2e\n", foot, worst);
    EXPECT_LE(worst, 1e-6) << foot;
  }
}

// Angular momentum about the touchdown point and linear momentum of the whole body, from the
// reference chain (velocities by complex step), in the frame of the configuration q.
struct Momenta {
  Eigen::Vector2d linear;
  double angular;
};

Momenta momenta(const WalkerModel<double>& m, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                const Eigen::Vector2d& point) {
  constexpr double h = 1e-30;
  const Eigen::VectorXcd qc = q.cast<std::complex<double>>() + std::complex<double>(0.0, h) * qd;
  const auto b = testing::bodies<std::complex<double>>(m, qc);
  const auto mass = testing::masses(m), J = testing::inertias(m);
  Momenta p{Eigen::Vector2d::Zero(), 0.0};
  for (int s = 0; s < m.segment_count; ++s) {
    const Eigen::Vector2d r = b.com[s].real() - point, v = b.com[s].imag() / h;
    p.linear += mass[s] * v;
    p.angular += mass[s] * (r.x() * v.y() - r.y() * v.x()) - J[s] * b.angle[s].imag() / h;  // angles turn clockwise
  }
  return p;
}

Eigen::Vector2d contact_point(const WalkerModel<double>& m, const testing::Bodies<double>& b, bool swing) {
  Eigen::Vector2d c = swing ? b.ankle2 : b.ankle1;
  if (m.has_feet()) {
    const auto fc = foot::rolling_contact(m.foot, (swing ? b.angle[6] : b.angle[5]) - m.foot_zero_angle);
    c += Eigen::Vector2d(fc.ddF, -fc.dF);  // eq. (5.5)
  }
  return c;
}

TEST(ImpactMap, ConservesAngularMomentumAboutTouchdownAndTransfersTheImpulse) {
  for (const char* foot : kReferenceFeet) {
    const auto& ref = testing::reference_gait(foot);
    ASSERT_TRUE(ref.start.real) << foot << ": " << ref.start.message;
    const WalkerModel<double>& m = ref.evaluator->model();
    const auto& tr = ref.start.gait.trajectory;
    const int last = static_cast<int>(tr.theta.size()) - 1;
    const Eigen::VectorXd q_minus = tr.q.col(last), qd_minus = tr.q_dot.col(last);
    const ImpactResult<double> imp = impact_map(m, CoordinateVector<double>(q_minus), CoordinateVector<double>(qd_minus));
    const auto b_minus = testing::bodies<double>(m, q_minus);
    const auto b_plus = testing::bodies<double>(m, Eigen::VectorXd(imp.q_plus));
    const Momenta before = momenta(m, q_minus, qd_minus, contact_point(m, b_minus, true));
    const Momenta after = momenta(m, imp.q_plus, imp.q_dot_plus, contact_point(m, b_plus, false));
    const double L_scale = std::abs(before.angular), p_scale = before.linear.norm();
    std::printf("%s: angular momentum about C2 %.9f -> %.9f; dp - F2 = %.2e N s\n", foot, before.angular, after.angular,
                (after.linear - before.linear - imp.impulse).norm());
    EXPECT_NEAR(after.angular, before.angular, 1e-10 * L_scale) << foot;
    EXPECT_LE((after.linear - before.linear - imp.impulse).norm(), 1e-10 * p_scale) << foot;
    EXPECT_LT(imp.kinetic_energy_plus, imp.kinetic_energy_minus) << foot;  // plastic impact dissipates
  }
}

}  // namespace
}  // namespace cyclopt::walker
