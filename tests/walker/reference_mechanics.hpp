#pragma once
// An independent, deliberately plain description of the walker for the tests: body positions from
// the kinematic chain of seed 001 Fig. 5.1 / eq. (5.3), (5.10) written out joint by joint, and
// energies from them (velocities by complex step). It shares no code with the slot form of
// walker_model.hpp / stance_dynamics.hpp, so agreement checks the Gram matrix, first moments,
// slot map and rolling slot.

#include "cyclopt/foot/foot_profile.hpp"
#include "cyclopt/walker/walker_model.hpp"

#include <array>
#include <complex>

namespace cyclopt::walker::testing {

template <class T>
struct Bodies {
  std::array<Eigen::Matrix<T, 2, 1>, kMaxSegments> com;  // centres of mass T, O1, O2, U1, U2, F1, F2
  std::array<T, kMaxSegments> angle;                     // absolute segment angles
  Eigen::Matrix<T, 2, 1> hip, knee1, knee2, ankle1, ankle2;
};

// q = [theta; H1; H2; K1; K2; (A1; A2)]; e(phi) = [sin phi; cos phi]; leg segments point from the
// proximal to the distal joint, CoM offsets r_* from the proximal joint, the foot CoM at r_F along
// theta_F from the ankle; the stance ankle rolls at [F_A; F'_A] (eq. 5.10a, x_0 = 0).
template <class T>
Bodies<T> bodies(const WalkerModel<double>& m, const Eigen::Matrix<T, Eigen::Dynamic, 1>& q) {
  using std::cos, std::sin;
  using V = Eigen::Matrix<T, 2, 1>;
  auto e = [](const T& phi) { return V(sin(phi), cos(phi)); };
  const auto& p = m.segments;
  Bodies<T> b;
  const T th_T = q(0) - q(1) - 0.5 * q(3);  // eq. (5.48)
  const T O1 = th_T + q(1), O2 = th_T + q(2), U1 = O1 + q(3), U2 = O2 + q(4);
  b.angle = {th_T, O1, O2, U1, U2, T(0.0), T(0.0)};
  b.ankle1 = V(T(0.0), T(0.0));
  if (m.has_feet()) {
    b.angle[5] = U1 + q(5);
    b.angle[6] = U2 + q(6);
    const auto c = foot::rolling_contact(m.foot, T(b.angle[5] - m.foot_zero_angle));
    b.ankle1 = V(c.F, c.dF);
  }
  b.knee1 = b.ankle1 - p[l_U] * e(U1);
  b.hip = b.knee1 - p[l_O] * e(O1);
  b.knee2 = b.hip + p[l_O] * e(O2);
  b.ankle2 = b.knee2 + p[l_U] * e(U2);
  b.com[seg_T] = b.hip + p[r_T] * e(th_T);
  b.com[seg_O1] = b.hip + p[r_O] * e(O1);
  b.com[seg_O2] = b.hip + p[r_O] * e(O2);
  b.com[seg_U1] = b.knee1 + p[r_U] * e(U1);
  b.com[seg_U2] = b.knee2 + p[r_U] * e(U2);
  b.com[seg_F1] = b.ankle1 + p[r_F] * e(b.angle[5]);
  b.com[seg_F2] = b.ankle2 + p[r_F] * e(b.angle[6]);
  return b;
}

inline std::array<double, kMaxSegments> masses(const WalkerModel<double>& m) {
  const auto& p = m.segments;
  return {p[m_T], p[m_O], p[m_O], p[m_U], p[m_U], m.has_feet() ? p[m_F] : 0.0, m.has_feet() ? p[m_F] : 0.0};
}
inline std::array<double, kMaxSegments> inertias(const WalkerModel<double>& m) {
  const auto& p = m.segments;
  return {p[J_T], p[J_O], p[J_O], p[J_U], p[J_U], m.has_feet() ? p[J_F] : 0.0, m.has_feet() ? p[J_F] : 0.0};
}

// Kinetic energy with velocities from one complex step along q_dot.
inline double kinetic_energy(const WalkerModel<double>& m, const Eigen::VectorXd& q, const Eigen::VectorXd& q_dot) {
  constexpr double h = 1e-30;
  const Eigen::VectorXcd qc = q.cast<std::complex<double>>() + std::complex<double>(0.0, h) * q_dot;
  const Bodies<std::complex<double>> b = bodies<std::complex<double>>(m, qc);
  const auto mass = masses(m), J = inertias(m);
  double E = 0.0;
  for (int s = 0; s < m.segment_count; ++s) {
    const Eigen::Vector2d v = b.com[s].imag() / h;
    const double w = b.angle[s].imag() / h;
    E += 0.5 * mass[s] * v.squaredNorm() + 0.5 * J[s] * w * w;
  }
  return E;
}

inline double potential_energy(const WalkerModel<double>& m, const Eigen::VectorXd& q) {
  const Bodies<double> b = bodies<double>(m, q);
  const auto mass = masses(m);
  double E = 0.0;
  for (int s = 0; s < m.segment_count; ++s) E += mass[s] * m.constants.gravity * b.com[s].y();
  return E;
}

}  // namespace cyclopt::walker::testing
