#pragma once
// Dynamics of the single-support phase (seed 001 eq. 5.13-5.16, 5.31-5.40, 5.73) in slot form.
//
// With E_kin = 1/2 sum G_st (w_s . w_t) u_s u_t + 1/2 sum J_s u_s^2 and E_pot = g sum G0_s w-integral
// (z of every body is z_A1 + sum L_bs cos phi_s), Lagrange's equations in slot angles give the
// slot forces
//   Q_s = w_s . A_s + J_s u_dot_s + g G0_s w_s,z,   A_s = sum_t G_st (u_dot_t w_t + u_t^2 w'_t),
// and, because slot angles are linear in q_s, the generalised forces are tau = slot_map^T Q:
// M_s q_dd + Gamma_s = tau = [0; u] (eq. 5.16, 5.17 with B_b = I). Every slot angle contains theta
// with coefficient 1, which makes the theta row a plain sum over slots.

#include "cyclopt/walker/stance_kinematics.hpp"

namespace cyclopt::walker {

template <class T>
using CoordinateMatrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxCoordinates, kMaxCoordinates>;

// Slot rates u = slot_map * q_dot.
template <class T, class MT>
SlotVector<T> slot_rates(const WalkerModel<MT>& m, const CoordinateVector<T>& q_dot) {
  return slot_combination(m, q_dot);
}

// Columns sum_t G_st a_t for every slot s. For scalars carrying derivatives plain loops beat
// Eigen's general matrix product (packing, dynamic sizes) at these sizes; doubles keep Eigen's.
template <class T, class MT>
Eigen::Matrix<T, 2, kMaxSlots> gram_weighted(const WalkerModel<MT>& m, const Eigen::Matrix<T, 2, kMaxSlots>& a) {
  Eigen::Matrix<T, 2, kMaxSlots> A;
  if constexpr (std::is_same_v<T, double>) {
    A.leftCols(m.slot_count) = a.leftCols(m.slot_count) * m.gram;
    return A;
  }
  for (int s = 0; s < m.slot_count; ++s) {
    Vec2<T> sum = Vec2<T>::Zero();
    for (int t = 0; t < m.slot_count; ++t) sum += a.col(t) * m.gram(t, s);
    A.col(s) = sum;
  }
  return A;
}

// P_s = sum_t G_st u_t w_t: the mass-weighted velocity sums every slot sees.
template <class T, class MT>
Eigen::Matrix<T, 2, kMaxSlots> slot_momenta(const WalkerModel<MT>& m, const StanceFrame<T>& f, const SlotVector<T>& u) {
  Eigen::Matrix<T, 2, kMaxSlots> wu = Eigen::Matrix<T, 2, kMaxSlots>::Zero();
  for (int t = 0; t < m.slot_count; ++t) wu.col(t) = f.w.col(t) * u(t);
  return gram_weighted(m, wu);
}

// Slot forces Q (see header comment) for rates u and slot accelerations u_dot.
template <class T, class MT>
SlotVector<T> slot_forces(const WalkerModel<MT>& m, const StanceFrame<T>& f, const SlotVector<T>& u,
                          const SlotVector<T>& u_dot) {
  const int n = m.slot_count;
  Eigen::Matrix<T, 2, kMaxSlots> a = Eigen::Matrix<T, 2, kMaxSlots>::Zero();
  for (int t = 0; t < n; ++t) a.col(t) = f.w.col(t) * u_dot(t) + f.dw.col(t) * (u(t) * u(t));
  const Eigen::Matrix<T, 2, kMaxSlots> A = gram_weighted(m, a);
  SlotVector<T> Q(n);
  const T g = T(m.constants.gravity);
  for (int s = 0; s < n; ++s) Q(s) = ad::dot(f.w.col(s), A.col(s)) + m.inertia(s) * u_dot(s) + g * m.first_moment(s) * f.w(1, s);
  return Q;
}

// Inverse dynamics: tau = M_s(q) q_dd + Gamma_s(q, q_dot) (eq. 5.16). tau(0) = 0 on a motion of the
// underactuated system; tau(1..) are the joint torques u of eq. (5.35).
template <class T, class MT>
CoordinateVector<T> generalized_forces(const WalkerModel<MT>& m, const StanceFrame<T>& f, const CoordinateVector<T>& q_dot,
                                       const CoordinateVector<T>& q_ddot) {
  return coordinate_combination(m, slot_forces(m, f, slot_rates(m, q_dot), slot_rates(m, q_ddot)));
}

// Mass matrix M_s(q) = slot_map^T D slot_map, D_st = G_st (w_s . w_t) + delta_st J_s (eq. 5.16).
template <class T, class MT>
CoordinateMatrix<T> mass_matrix(const WalkerModel<MT>& m, const StanceFrame<T>& f) {
  const int n = m.slot_count;
  SlotMatrix<T> D(n, n);
  for (int s = 0; s < n; ++s)
    for (int t = s; t < n; ++t) D(s, t) = D(t, s) = m.gram(s, t) * ad::dot(f.w.col(s), f.w.col(t));
  for (int s = 0; s < n; ++s) D(s, s) += m.inertia(s);
  const auto S = m.slot_map.template cast<T>();
  return S.transpose() * D * S;
}

// Ground reaction on the stance foot (eq. 5.14), from the total momentum balance
// F_1 = sum_b m_b a_b + m g e_z, with sum_b m_b a_b = sum_s G0_s (w_s u_dot_s + w'_s u_s^2).
template <class T, class MT>
Vec2<T> stance_contact_force(const WalkerModel<MT>& m, const StanceFrame<T>& f, const CoordinateVector<T>& q_dot,
                             const CoordinateVector<T>& q_ddot) {
  const SlotVector<T> u = slot_rates(m, q_dot), u_dot = slot_rates(m, q_ddot);
  Vec2<T> F(T(0.0), m.total_mass * T(m.constants.gravity));
  for (int s = 0; s < m.slot_count; ++s) F += m.first_moment(s) * (f.w.col(s) * u_dot(s) + f.dw.col(s) * (u(s) * u(s)));
  return F;
}

// Kinetic and potential energy at (q, q_dot).
template <class T, class MT>
T kinetic_energy(const WalkerModel<MT>& m, const StanceFrame<T>& f, const CoordinateVector<T>& q_dot) {
  return 0.5 * ad::dot(q_dot, mass_matrix(m, f) * q_dot);
}

// E_pot = g sum_b m_b z_b with z_b = z_A1 + sum_j L_bj cos phi_j.
template <class T, class MT>
T potential_energy(const WalkerModel<MT>& m, const StanceFrame<T>& f) {
  using std::cos;
  T z = m.total_mass * f.stance_ankle.y();
  for (int s = 0; s < m.segment_count; ++s) z += m.first_moment(s) * cos(f.angle(s));
  return T(m.constants.gravity) * z;
}

// Dynamics on the virtual constraint q_b = q_b,d(theta) at one configuration (eq. 5.16, 5.35,
// 5.14, 5.71-5.73). With q_dot = gamma theta_dot and q_dd = gamma theta_dd + gamma' theta_dot^2,
// gamma = [1; q_b,d'], gamma' = [0; q_b,d''], the slot rates are u theta_dot and the slot
// accelerations u theta_dd + u2 theta_dot^2 (u = slot_map gamma, u2 = slot_map gamma'), so the
// generalised forces and the stance contact force are affine in (theta_dd, theta_dot^2):
//   tau = inertial theta_dd + coupled theta_dot^2 + gravity                    (5.16, 5.35)
//   F_1 = force_inertial theta_dd + force_coupled theta_dot^2 + m g e_z        (5.14)
// One evaluation per grid point serves the zero dynamics (the theta rows, tau_0 = 0) and the
// reconstruction of torques and contact forces once theta_dot is known.
template <class T>
struct ConstrainedDynamics {
  CoordinateVector<T> inertial, coupled, gravity;  // M_s gamma;  M_s gamma' + Gamma_s(gamma);  g-terms
  Vec2<T> force_inertial, force_coupled;
  T kinetic_slope;  // d E_kin / d theta per theta_dot^2
};

template <class T, class MT>
ConstrainedDynamics<T> constrained_dynamics(const WalkerModel<MT>& m, const StanceFrame<T>& f,
                                            const CoordinateVector<T>& gamma, const CoordinateVector<T>& gamma_prime) {
  const int n = m.slot_count;
  const SlotVector<T> u = slot_rates(m, gamma);         // slot rates per unit theta_dot
  const SlotVector<T> u2 = slot_rates(m, gamma_prime);  // slot accelerations per theta_dot^2
  const Eigen::Matrix<T, 2, kMaxSlots> P = slot_momenta(m, f, u);
  Eigen::Matrix<T, 2, kMaxSlots> a2 = Eigen::Matrix<T, 2, kMaxSlots>::Zero();
  for (int t = 0; t < n; ++t) a2.col(t) = f.w.col(t) * u2(t) + f.dw.col(t) * (u(t) * u(t));
  const Eigen::Matrix<T, 2, kMaxSlots> A2 = gram_weighted(m, a2);
  // Slot forces of the three parts (slot_forces with u_dot = u, u_dot = u2 + u^2 w', gravity).
  SlotVector<T> Q1(n), Q2(n), Qg(n);
  ConstrainedDynamics<T> d;
  d.force_inertial.setZero();
  d.force_coupled.setZero();
  d.kinetic_slope = T(0.0);
  const double g = m.constants.gravity;
  for (int s = 0; s < n; ++s) {
    Q1(s) = ad::dot(f.w.col(s), P.col(s)) + m.inertia(s) * u(s);
    Q2(s) = ad::dot(f.w.col(s), A2.col(s)) + m.inertia(s) * u2(s);
    Qg(s) = (g * m.first_moment(s)) * f.w(1, s);
    d.force_inertial += m.first_moment(s) * (f.w.col(s) * u(s));
    d.force_coupled += m.first_moment(s) * a2.col(s);
    d.kinetic_slope += u(s) * ad::dot(f.dw.col(s), P.col(s));
  }
  d.inertial = coordinate_combination(m, Q1);
  d.coupled = coordinate_combination(m, Q2);
  d.gravity = coordinate_combination(m, Qg);
  return d;
}

// Zero dynamics (eq. 5.71, 5.73): theta_dot = nu1 sigma, sigma_dot = nu2 + nu3 sigma^2, and
// theta_dd = -(b theta_dot^2 + c) / a (equivalent to eq. 5.95, without differentiating nu1
// numerically) from the theta row tau_0 = 0: a = 1/nu1 = e_1^T M_s gamma, b, c.
template <class T>
struct ZeroDynamicsCoefficients {
  T nu1, nu2, nu3;
  T a, b, c;
};

template <class T>
ZeroDynamicsCoefficients<T> zero_dynamics_coefficients(const ConstrainedDynamics<T>& d) {
  ZeroDynamicsCoefficients<T> z;
  z.a = d.inertial(0);
  z.b = d.coupled(0);
  z.c = d.gravity(0);
  z.nu1 = 1.0 / z.a;
  z.nu2 = -z.c;                             // -dE_pot/dtheta (eq. 5.38 with the sign of Lagrange's equation)
  z.nu3 = z.nu1 * z.nu1 * d.kinetic_slope;  // dE_kin/dtheta with theta_dot = nu1 sigma
  return z;
}

}  // namespace cyclopt::walker
