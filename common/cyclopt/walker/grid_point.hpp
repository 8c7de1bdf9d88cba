#pragma once
// One grid point of the periodic gait (seed 001 eq. 5.93): everything periodic_gait takes from the
// stance phase at q = [theta_i; q_b,d(theta_i)] with gamma = [1; q_b,d'] and gamma' = [0; q_b,d'']:
// the dynamics on the constraint (eq. 5.14, 5.16, 5.35, 5.73, see ConstrainedDynamics), the hip,
// the swing contact point (eq. 5.5) and the stance foot angle.
//
// Local derivatives. For a double model and Dual<N> states the point depends on the N directions
// only through q, gamma, gamma' (q_b,d = alpha B is linear in the Bezier coefficients, eq. 5.49-5.52),
// so the values and their Jacobians with respect to these local inputs are computed once in double
// and chained with the inputs' derivative parts: no Dual arithmetic inside the mechanics. In slot
// form (stance_dynamics.hpp), with slot angles psi = S q, rates u = S gamma, u2 = S gamma' and
//   D_st = G_st (w_s . w_t) + delta_st J_s,   E_st = G_st (w_s . w'_t),
//   H_st = G_st (w'_s . w'_t),               K_st = G_st (w_s . w''_t),
// (w'' = dw'/dpsi: -w for a segment, [F'''; F''''] for the rolling ankle) the slot forces are
//   Q1 = D u,   Q2 = D u2 + E (u o u),   Qg_s = g G0_s w_s,z,
// and because w_s depends on psi_s alone, dD_st/dpsi_k = delta_sk E_ts + delta_tk E_st and
// dE_st/dpsi_k = delta_sk H_st + delta_tk K_st. Generalised forces are S^T Q (eq. 5.16).

#include "cyclopt/walker/stance_dynamics.hpp"

#include <type_traits>

namespace cyclopt::walker {

template <class T>
struct GridPoint {
  ConstrainedDynamics<T> dynamics;
  Vec2<T> hip;              // [x_H; z_H]
  Vec2<T> swing_contact;    // [x_C2; z_C2]
  T stance_foot_angle{};    // theta_F1 (feet only)
};

namespace detail {

// Derivative parts of a few Duals, one row each (contiguous, so rows combine as vector updates).
template <int N>
using DerivativeRows = Eigen::Matrix<double, Eigen::Dynamic, N, Eigen::RowMajor, kMaxSlots, N>;
using LocalJacobian = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSlots, kMaxSlots>;

// d += J X, row by row; zeros of J skipped (S, G and so every slot Jacobian are sparse). Each row of
// X is loaded once and added to every row of d that needs it.
template <int N, class Jacobian>
void add_product(const Jacobian& J, const DerivativeRows<N>& X, DerivativeRows<N>& d) {
  for (int j = 0; j < J.cols(); ++j) {
    const Eigen::Matrix<double, 1, N> x = X.row(j);
    for (int k = 0; k < J.rows(); ++k)
      if (J(k, j) != 0.0) d.row(k) += J(k, j) * x;
  }
}

// Duals with values v and derivative rows d.
template <int N, class Out>
void assign(const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxSlots, 1>& v, const DerivativeRows<N>& d, Out& out) {
  out.resize(v.size());
  for (int k = 0; k < v.size(); ++k) {
    out(k).v = v(k);
    out(k).d = d.row(k).transpose();
  }
}

template <int N>
void chained_grid_point(const WalkerModel<double>& m, const CoordinateVector<ad::Dual<N>>& q,
                        const CoordinateVector<ad::Dual<N>>& gamma, const CoordinateVector<ad::Dual<N>>& gamma_prime,
                        GridPoint<ad::Dual<N>>& p) {
  using Dual = ad::Dual<N>;
  const int n = m.slot_count, nq = static_cast<int>(q.size()), ns = m.segment_count;
  CoordinateVector<double> qv(nq), gv(nq), g1v(nq);
  DerivativeRows<N> dq(nq, N), dg(nq, N), dg1(nq, N);
  for (int k = 0; k < nq; ++k) {
    qv(k) = q(k).v;
    gv(k) = gamma(k).v;
    g1v(k) = gamma_prime(k).v;
    dq.row(k) = q(k).d.transpose();
    dg.row(k) = gamma(k).d.transpose();
    dg1.row(k) = gamma_prime(k).d.transpose();
  }
  // Values (the double path itself) and the slot quantities of the header comment.
  const StanceFrame<double> f = stance_frame(m, qv);
  const ConstrainedDynamics<double> cd = constrained_dynamics(m, f, gv, g1v);
  const SlotVector<double> u = m.slot_map * gv, u2 = m.slot_map * g1v, uu = u.cwiseProduct(u);
  Eigen::Matrix<double, 2, kMaxSlots> ddw = -f.w;
  if (m.has_feet()) {
    const int r = m.rolling_slot();
    const auto c = foot::rolling_contact(m.foot, ad::Dual<1>::variable(f.angle(seg_F1) - m.foot_zero_angle, 0));
    ddw.col(r) << f.stance_foot.dddF, c.dddF.d(0);
  }
  SlotMatrix<double> D(n, n), E(n, n), H(n, n), K(n, n);
  for (int s = 0; s < n; ++s)
    for (int t = 0; t < n; ++t) {
      const double G = m.gram(s, t);
      D(s, t) = G * f.w.col(s).dot(f.w.col(t));
      E(s, t) = G * f.w.col(s).dot(f.dw.col(t));
      H(s, t) = G * f.dw.col(s).dot(f.dw.col(t));
      K(s, t) = G * f.w.col(s).dot(ddw.col(t));
    }
  D.diagonal() += m.inertia.head(n);
  // Slot Jacobians with respect to psi (J*_p), u (J*_u) and u2.
  LocalJacobian JQ1_p = E * u.asDiagonal(), JQ2_p = E * u2.asDiagonal() + K * uu.asDiagonal();
  JQ1_p.diagonal() += E.transpose() * u;
  JQ2_p.diagonal() += E.transpose() * u2 + H * uu;
  const LocalJacobian JQ2_u = 2.0 * E * u.asDiagonal();
  LocalJacobian JQg_p = LocalJacobian::Zero(n, n);
  LocalJacobian JFi_p(2, n), JFi_u(2, n), JFc_p(2, n), JFc_u(2, n);
  const double g = m.constants.gravity;
  for (int s = 0; s < n; ++s) {
    const double G0 = m.first_moment(s);
    JQg_p(s, s) = g * G0 * f.dw(1, s);
    JFi_p.col(s) = G0 * u(s) * f.dw.col(s);
    JFi_u.col(s) = G0 * f.w.col(s);
    JFc_p.col(s) = G0 * (u2(s) * f.dw.col(s) + uu(s) * ddw.col(s));
    JFc_u.col(s) = 2.0 * G0 * u(s) * f.dw.col(s);
  }
  const LocalJacobian Jks_p = (u.cwiseProduct(H * u + K.transpose() * u)).transpose();
  const LocalJacobian Jks_u = ((E + E.transpose()) * u).transpose();
  // Hip and swing contact point: d e(psi_s)/dpsi_s = w_s; the stance ankle [F; F'] moves with the
  // rolling slot ([F'; F''] = its w), the swing foot's [F''; -F'] with psi_F2.
  LocalJacobian Jhip_p = LocalJacobian::Zero(2, n), Jswing_p = LocalJacobian::Zero(2, n);
  for (int s = 0; s < ns; ++s) {
    Jhip_p.col(s) = m.hip(s) * f.w.col(s);
    Jswing_p.col(s) = m.swing_ankle(s) * f.w.col(s);
  }
  if (m.has_feet()) {
    Jhip_p.col(m.rolling_slot()) += f.w.col(m.rolling_slot());
    Jswing_p.col(m.rolling_slot()) += f.w.col(m.rolling_slot());
    Jswing_p.col(seg_F2) += Eigen::Vector2d(f.swing_foot.dddF, -f.swing_foot.ddF);
  }
  // Chain rule in slot form: derivative rows of psi, u, u2 are S (dq, dgamma, dgamma'), those of
  // the generalised forces S^T (those of Q).
  const SlotMap& S = m.slot_map;
  const LocalJacobian St = S.transpose();
  auto rows = [](int r) { return DerivativeRows<N>::Zero(r, N).eval(); };
  DerivativeRows<N> dpsi = rows(n), du = rows(n), du2 = rows(n);
  add_product<N>(S, dq, dpsi);
  add_product<N>(S, dg, du);
  add_product<N>(S, dg1, du2);
  DerivativeRows<N> dQ1 = rows(n), dQ2 = rows(n), dQg = rows(n), dtau = rows(nq);
  add_product<N>(JQ1_p, dpsi, dQ1);
  add_product<N>(D, du, dQ1);
  add_product<N>(JQ2_p, dpsi, dQ2);
  add_product<N>(JQ2_u, du, dQ2);
  add_product<N>(D, du2, dQ2);
  add_product<N>(JQg_p, dpsi, dQg);
  ConstrainedDynamics<Dual>& d = p.dynamics;
  add_product<N>(St, dQ1, dtau);
  assign<N>(cd.inertial, dtau, d.inertial);
  dtau.setZero();
  add_product<N>(St, dQ2, dtau);
  assign<N>(cd.coupled, dtau, d.coupled);
  dtau.setZero();
  add_product<N>(St, dQg, dtau);
  assign<N>(cd.gravity, dtau, d.gravity);
  DerivativeRows<N> dv = rows(2);
  add_product<N>(JFi_p, dpsi, dv);
  add_product<N>(JFi_u, du, dv);
  assign<N>(cd.force_inertial, dv, d.force_inertial);
  dv.setZero();
  add_product<N>(JFc_p, dpsi, dv);
  add_product<N>(JFc_u, du, dv);
  add_product<N>(JFi_u, du2, dv);
  assign<N>(cd.force_coupled, dv, d.force_coupled);
  dv.setZero();
  add_product<N>(Jhip_p, dpsi, dv);
  assign<N>(point_position(f, m.hip), dv, p.hip);
  dv.setZero();
  add_product<N>(Jswing_p, dpsi, dv);
  assign<N>(swing_contact_point(m, f), dv, p.swing_contact);
  DerivativeRows<N> dks = rows(1);
  add_product<N>(Jks_p, dpsi, dks);
  add_product<N>(Jks_u, du, dks);
  d.kinetic_slope.v = cd.kinetic_slope;
  d.kinetic_slope.d = dks.row(0).transpose();
  if (m.has_feet()) {
    p.stance_foot_angle.v = f.angle(seg_F1);
    p.stance_foot_angle.d = dpsi.row(seg_F1).transpose();
  }
}

}  // namespace detail

// Fills p (in place: for Duals the point is large and written once).
template <class T, class MT>
void grid_point(const WalkerModel<MT>& m, const CoordinateVector<T>& q, const CoordinateVector<T>& gamma,
                const CoordinateVector<T>& gamma_prime, GridPoint<T>& p) {
  if constexpr (ad::is_dual_v<T> && std::is_same_v<MT, double>) {
    detail::chained_grid_point(m, q, gamma, gamma_prime, p);
  } else {
    const StanceFrame<T> f = stance_frame(m, q);
    p.dynamics = constrained_dynamics(m, f, gamma, gamma_prime);
    p.hip = point_position(f, m.hip);
    p.swing_contact = swing_contact_point(m, f);
    if (m.has_feet()) p.stance_foot_angle = f.angle(seg_F1);
  }
}

}  // namespace cyclopt::walker
