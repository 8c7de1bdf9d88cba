#pragma once
// Kinematics of the single-support phase (seed 001 section 5.1.3) in slot form (walker_model.hpp):
// at a configuration q_s = [theta; q_b] every slot s has a velocity direction w_s and its
// derivative w'_s with respect to the slot angle:
//   segment j:     w = d e/d phi = [cos phi; -sin phi],  w' = -e(phi)
//   rolling ankle: w = r'_A1 = [F'_A; F''_A],            w' = [F''_A; F'''_A]      (eq. 5.10)
// so that every point velocity is sum_s L_s w_s u_s with slot rates u = slot_map * q_s_dot.
//
// Every function takes the model with its own scalar MT and the state with scalar T: a double
// model with Dual or complex states keeps the model's constants plain doubles (products with them
// cost N, not 3N, per Dual); with free model parameters MT = T.

#include "cyclopt/walker/walker_model.hpp"

#include "cyclopt/foot/rolling_kinematics.hpp"

#include <cmath>
#include <type_traits>

namespace cyclopt::walker {

template <class T>
using Vec2 = Eigen::Matrix<T, 2, 1>;

template <class T>
struct StanceFrame {
  SlotVector<T> angle;  // slot angles phi_s
  Eigen::Matrix<T, 2, kMaxSlots> w;   // columns w_s
  Eigen::Matrix<T, 2, kMaxSlots> dw;  // columns w'_s
  foot::RollingContact<T> stance_foot{};  // F_A and derivatives at theta_F1 (feet only)
  foot::RollingContact<T> swing_foot{};   // at theta_F2 (feet only)
  Vec2<T> stance_ankle;                   // r_A1 = [F_A; F'_A] (x_0 = 0), or 0 for point feet
};

// e(phi) = [sin phi; cos phi]: direction of a segment at absolute angle phi.
template <class T>
Vec2<T> direction(const T& phi) {
  using std::cos, std::sin;
  return Vec2<T>(sin(phi), cos(phi));
}

// F_A(theta_F) = F(theta_F - theta_F,0) of the model's foot (eq. 5.4). F depends on the one angle
// only: for Dual angles on a double model, F..F''' and their theta-derivatives F'..F'''' come from
// one pass with a single direction, chained with the angle's derivatives.
template <class T, class MT>
foot::RollingContact<T> foot_contact(const WalkerModel<MT>& m, const T& theta_F) {
  if constexpr (ad::is_dual_v<T> && std::is_same_v<MT, double>) {
    const auto c = foot::rolling_contact(m.foot, ad::Dual<1>::variable(theta_F.v - m.foot_zero_angle, 0));
    auto chained = [&](const ad::Dual<1>& f) { return T(f.v, f.d(0) * theta_F.d); };
    return {chained(c.F), chained(c.dF), chained(c.ddF), chained(c.dddF)};
  } else {
    return foot::rolling_contact(m.foot, T(theta_F - m.foot_zero_angle));
  }
}

// slot_map * v for any coordinate-shaped v. slot_map holds a few entries 0, +-1, +-1/2: for
// scalars carrying derivatives, scalar multiples of the nonzero ones avoid the casts and full
// products of a dense product with slot_map cast to T; doubles keep Eigen's vectorised product.
template <class T, class MT>
SlotVector<T> slot_combination(const WalkerModel<MT>& m, const CoordinateVector<T>& v) {
  if constexpr (std::is_same_v<T, double>) return m.slot_map * v;
  SlotVector<T> r(m.slot_count);
  for (int s = 0; s < m.slot_count; ++s) {
    T sum = T(0.0);
    for (int k = 0; k < v.size(); ++k)
      if (m.slot_map(s, k) != 0.0) sum += m.slot_map(s, k) * v(k);
    r(s) = sum;
  }
  return r;
}

// slot_map^T * Q: slot forces to generalised forces (same scheme).
template <class T, class MT>
CoordinateVector<T> coordinate_combination(const WalkerModel<MT>& m, const SlotVector<T>& Q) {
  if constexpr (std::is_same_v<T, double>) return m.slot_map.transpose() * Q;
  CoordinateVector<T> r(m.slot_map.cols());
  for (int k = 0; k < r.size(); ++k) {
    T sum = T(0.0);
    for (int s = 0; s < m.slot_count; ++s)
      if (m.slot_map(s, k) != 0.0) sum += m.slot_map(s, k) * Q(s);
    r(k) = sum;
  }
  return r;
}

template <class T, class MT>
StanceFrame<T> stance_frame(const WalkerModel<MT>& m, const CoordinateVector<T>& q) {
  using std::cos, std::sin;
  StanceFrame<T> f;
  f.angle = slot_combination(m, q);
  for (int s = 0; s < m.segment_count; ++s) {
    const T c = cos(f.angle(s)), sn = sin(f.angle(s));
    f.w.col(s) << c, -sn;
    f.dw.col(s) << -sn, -c;
  }
  f.stance_ankle.setZero();
  if (m.has_feet()) {
    f.stance_foot = foot_contact(m, f.angle(seg_F1));
    f.swing_foot = foot_contact(m, f.angle(seg_F2));
    const int r = m.rolling_slot();
    f.w.col(r) << f.stance_foot.dF, f.stance_foot.ddF;
    f.dw.col(r) << f.stance_foot.ddF, f.stance_foot.dddF;
    f.stance_ankle << f.stance_foot.F, f.stance_foot.dF;
  }
  return f;
}

// Position of a point given by its segment offsets from the stance ankle (direction e(phi_s) =
// -w'_s of the frame, so no angle is evaluated twice).
template <class T, class MT>
Vec2<T> point_position(const StanceFrame<T>& f, const SegmentOffsets<MT>& offsets) {
  Vec2<T> r = f.stance_ankle;
  for (int s = 0; s < offsets.size(); ++s) r -= offsets(s) * f.dw.col(s);
  return r;
}

// Velocity of that point for slot rates u (the rolling slot carries the ankle's own motion).
template <class T, class MT>
Vec2<T> point_velocity(const WalkerModel<MT>& m, const StanceFrame<T>& f, const SegmentOffsets<MT>& offsets,
                       const SlotVector<T>& u) {
  Vec2<T> v = Vec2<T>::Zero();
  for (int s = 0; s < offsets.size(); ++s) v += offsets(s) * f.w.col(s) * u(s);
  if (m.has_feet()) v += f.w.col(m.rolling_slot()) * u(m.rolling_slot());
  return v;
}

// Potential contact point of the swing foot, C2 = A2 + F''_A e_x - F'_A e_z (eq. 5.5); for
// point feet the swing ankle itself.
template <class T, class MT>
Vec2<T> swing_contact_point(const WalkerModel<MT>& m, const StanceFrame<T>& f) {
  Vec2<T> c = point_position(f, m.swing_ankle);
  if (m.has_feet()) c += Vec2<T>(f.swing_foot.ddF, -f.swing_foot.dF);
  return c;
}

// Its velocity: the swing ankle's velocity minus theta_F2_dot [F'_A; F''_A] (a material point of
// the rigid foot; equal to the rate of the lowest point because the sole is convex).
template <class T, class MT>
Vec2<T> swing_contact_velocity(const WalkerModel<MT>& m, const StanceFrame<T>& f, const SlotVector<T>& u) {
  Vec2<T> v = point_velocity(m, f, m.swing_ankle, u);
  if (m.has_feet()) v -= u(seg_F2) * Vec2<T>(f.swing_foot.dF, f.swing_foot.ddF);
  return v;
}

}  // namespace cyclopt::walker
