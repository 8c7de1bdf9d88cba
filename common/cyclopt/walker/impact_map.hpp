#pragma once
// Double-support phase as an instantaneous plastic impact of the swing foot with leg swap (seed 001
// eq. 5.21-5.28, 5.41-5.44). The free model adds the stance-ankle translation [x_A1; z_A1] to
// q_hat_s = [theta_T; q_b]; its mass matrix in slot form has two translation slots with constant
// directions e_x, e_z and offset 1 for every body. The impact solves
//   [M_f  -G_2^T; G_2  0] [q_f+; F_2] = [M_f q_f-; 0]      (eq. 5.26)
// with G_2 the Jacobian of the material velocity of the swing contact point C2 (eq. 5.25), then
// swaps the legs (eq. 5.41) and returns to q_s = [theta; q_b] (eq. 5.42-5.43).

#include "cyclopt/walker/stance_dynamics.hpp"

#include <Eigen/LU>

namespace cyclopt::walker {

template <class T>
struct ImpactResult {
  CoordinateVector<T> q_plus;      // q_s+ (legs swapped)
  CoordinateVector<T> q_dot_plus;  // q_s_dot+
  Vec2<T> impulse;                 // F_hat_2 = [F_2x; F_2z] (N s), eq. (5.28)
  T kinetic_energy_minus;          // before the impact
  T kinetic_energy_plus;           // after
};

// q_hat_s = [theta_T; q_b] from q_s = [theta; q_b] (inverse of eq. 5.48) and back.
template <class T>
T torso_angle(const CoordinateVector<T>& q) {
  return q(0) - q(1 + joint_H1) - 0.5 * q(1 + joint_K1);
}

// Relabels the legs, eq. (5.41): swaps H1<->H2, K1<->K2, A1<->A2 of a q_b-shaped block.
template <class T>
JointVector<T> swap_legs(const JointVector<T>& qb) {
  JointVector<T> r(qb.size());
  for (int j = 0; j < qb.size(); j += 2) {
    r(j) = qb(j + 1);
    r(j + 1) = qb(j);
  }
  return r;
}

// Configuration map Delta_q (eq. 5.42): theta_T unchanged, legs swapped.
template <class T>
CoordinateVector<T> swap_configuration(const CoordinateVector<T>& q) {
  const int nb = static_cast<int>(q.size()) - 1;
  CoordinateVector<T> r(q.size());
  r.tail(nb) = swap_legs<T>(q.tail(nb));
  r(0) = torso_angle(q) + r(1 + joint_H1) + 0.5 * r(1 + joint_K1);
  return r;
}

template <class T, class MT>
ImpactResult<T> impact_map(const WalkerModel<MT>& m, const CoordinateVector<T>& q_minus,
                           const CoordinateVector<T>& q_dot_minus) {
  const int nb = m.joint_count, ns = m.segment_count, nf = nb + 3;  // [x, z, theta_T, q_b]
  const StanceFrame<T> f = stance_frame(m, q_minus);
  // Segment angles in q_hat_s (eq. 5.3): d phi / d q_hat_s. Column 0 is theta_T.
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSegments, kMaxCoordinates> Sh(ns, nb + 1);
  for (int s = 0; s < ns; ++s) {
    Sh.row(s) = m.slot_map.row(s);
    Sh(s, 1 + joint_H1) += 1.0;  // q_s -> q_hat_s: theta = theta_T + H1 + K1/2
    Sh(s, 1 + joint_K1) += 0.5;
  }
  using Mat = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxCoordinates + 2 + 2, kMaxCoordinates + 2 + 2>;
  // Translation + segment "slot" directions as columns of W (2 x (2 + ns)).
  Eigen::Matrix<T, 2, Eigen::Dynamic, 0, 2, kMaxSegments + 2> W(2, ns + 2);
  W.setZero();
  W(0, 0) = T(1.0);
  W(1, 1) = T(1.0);
  for (int s = 0; s < ns; ++s) W.col(2 + s) = f.w.col(s);
  // Slot Jacobian: slot rates = Sf * q_f_dot.
  Mat Sf = Mat::Zero(ns + 2, nf);
  Sf(0, 0) = T(1.0);
  Sf(1, 1) = T(1.0);
  Sf.block(2, 2, ns, nb + 1) = Sh.template cast<T>();
  // Free-model slot Gram matrix (translations carry offset 1 for every body) and D.
  Mat D(ns + 2, ns + 2);
  for (int s = 0; s < ns + 2; ++s)
    for (int t = s; t < ns + 2; ++t) {
      MT g;
      if (s < 2 && t < 2) g = m.total_mass;
      else if (s < 2) g = m.first_moment(t - 2);
      else g = m.gram(s - 2, t - 2);
      D(s, t) = D(t, s) = g * ad::dot(W.col(s), W.col(t));
    }
  for (int s = 0; s < ns; ++s) D(2 + s, 2 + s) += m.inertia(s);
  const Mat Mf = Sf.transpose() * D * Sf;
  // Material velocity of C2 (eq. 5.24-5.25): translation + swing-ankle offsets (+ foot rotation).
  Eigen::Matrix<T, 2, Eigen::Dynamic, 0, 2, kMaxCoordinates + 2> G2 = Eigen::Matrix<T, 2, Eigen::Dynamic, 0, 2, kMaxCoordinates + 2>::Zero(2, nf);
  G2(0, 0) = T(1.0);
  G2(1, 1) = T(1.0);
  for (int s = 0; s < ns; ++s) G2.rightCols(nb + 1) += (m.swing_ankle(s) * f.w.col(s)) * Sh.row(s).template cast<T>();
  if (m.has_feet())
    G2.rightCols(nb + 1) -= Vec2<T>(f.swing_foot.dF, f.swing_foot.ddF) * Sh.row(seg_F2).template cast<T>();
  // Pre-impact free velocities (eq. 5.22): stance ankle rolls, theta_T_dot from eq. (5.48).
  Eigen::Matrix<T, Eigen::Dynamic, 1, 0, kMaxCoordinates + 2, 1> qf_dot(nf);
  qf_dot.setZero();
  if (m.has_feet()) qf_dot.head(2) = f.w.col(m.rolling_slot()) * ad::dot(m.slot_map.row(seg_F1).template cast<T>().transpose(), q_dot_minus);
  qf_dot(2) = torso_angle(q_dot_minus);
  qf_dot.tail(nb) = q_dot_minus.tail(nb);
  // KKT system (eq. 5.26).
  Mat K = Mat::Zero(nf + 2, nf + 2);
  K.topLeftCorner(nf, nf) = Mf;
  K.block(0, nf, nf, 2) = -G2.transpose();
  K.block(nf, 0, 2, nf) = G2;
  Eigen::Matrix<T, Eigen::Dynamic, 1, 0, kMaxCoordinates + 4, 1> rhs(nf + 2);
  rhs.head(nf) = Mf * qf_dot;
  rhs.tail(2).setZero();
  const auto sol = K.partialPivLu().solve(rhs).eval();
  ImpactResult<T> r;
  r.impulse = sol.segment(nf, 2);
  r.kinetic_energy_minus = 0.5 * ad::dot(qf_dot, Mf * qf_dot);
  const auto qf_plus = sol.head(nf).eval();
  r.kinetic_energy_plus = 0.5 * ad::dot(qf_plus, Mf * qf_plus);
  // Swap legs (eq. 5.41) and go back to theta (eq. 5.43).
  r.q_plus = swap_configuration(q_minus);
  r.q_dot_plus.resize(nb + 1);
  r.q_dot_plus.tail(nb) = swap_legs<T>(qf_plus.tail(nb));
  r.q_dot_plus(0) = qf_plus(2) + r.q_dot_plus(1 + joint_H1) + 0.5 * r.q_dot_plus(1 + joint_K1);
  return r;
}

}  // namespace cyclopt::walker
