#pragma once
// The rolling-contact function F(theta) of a regularised convex polygon (seed 001, ch. 2-3).
//
// A foot profile is a sum of regularised transitions, one per polygon edge i with length l_i,
// orientation delta_i and regularisation k_i (eq. 3.19 / 3.22):
//
//   F(theta) = 1/2 sum_i l_i (k_i^2 + 1 - cos(a_i)) H_i(a_i),   a_i = theta - delta_i,
//   H_i(a)   = 1 + tanh(a/k_i) + sum_{n=1..N} [tanh((a - 2 pi n)/k_i) + tanh((a + 2 pi n)/k_i)]
//
// where the sum over n is the optional finite periodic continuation of eq. (3.18) (N = 0 by
// default, as in the seed). With F, the ankle of a foot rolling on flat ground is at
// x_A = F + x_0, z_A = F' (eq. 3.9, 3.10a, 5.10a), the contact point relative to the ankle is
// r_AC = F'' e_x - F' e_z (eq. 5.5) and the curvature radius is R = F' + F''' (eq. 2.34, 3.10c).
//
// Numerics: every tanh is evaluated from e = exp(-2|u|) in (0, 1], so no term overflows and
// 1 + tanh(u) keeps full relative accuracy for u << 0 (where the naive form cancels). The
// curvature radius is summed from the closed form of eq. (3.14) per tanh term, each of which is
// non-negative by appendix A, instead of adding F' and F''' (which cancel to rounding noise
// away from the transitions). 1 - cos(a) is evaluated as 2 sin^2(a/2).

#include "cyclopt/autodiff/scalar.hpp"
#include "cyclopt/foot/foot_parameters.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <utility>

namespace cyclopt::foot {

// One regularised transition: the edge of the generating polygon that lies flat on the ground
// at theta = delta (eq. 3.20 / 3.23).
template <class S>
struct Transition {
  S length;  // l_i (m)
  S angle;   // delta_i (rad)
  S k;       // k_i (rad)
};

// Everything needed to evaluate F for one foot: built once from the parameters by make_profile().
template <class S>
struct FootProfile {
  FootModel model = FootModel::point;
  std::array<Transition<S>, 4> transitions{};
  int transition_count = 0;  // 0 for the point foot, 3 for HM, 4 for HMT
  int periodic_terms = 0;    // N of the periodic continuation (eq. 3.18)
  // Admissible foot angles: contact stays on the sole (end of section 3.3.1 / 3.3.2).
  S theta_min = S(-std::numbers::pi);
  S theta_max = S(std::numbers::pi);
};

// F and its first three derivatives with respect to theta at one angle.
template <class T>
struct RollingContact {
  T F;     // F(theta): horizontal ankle position minus x_0 (m)
  T dF;    // F'(theta): ankle height z_A (m)
  T ddF;   // F''(theta): horizontal offset ankle -> contact point (m)
  T dddF;  // F'''(theta) (m)
};

namespace detail {

using std::cos;
using std::exp;
using std::sin;

// tanh(u) and its derivatives with respect to u, plus the "step" 1 + sign(u) * ... split so that
// sums of steps stay exact: tanh(u) = sign - sign * tail, tail = 2e/(1+e) in [0, 1].
template <class T>
struct TanhTerm {
  double sign;  // +1 for u >= 0, -1 otherwise
  T tail;       // 2e/(1+e), e = exp(-2|u|)
  T t;          // tanh(u)
  T s;          // 1 - tanh^2(u)
};

template <class T>
TanhTerm<T> tanh_term(const T& u) {
  const double sign = ad::value(u) >= 0.0 ? 1.0 : -1.0;
  const T e = exp(-2.0 * sign * u);
  const T one_plus_e = 1.0 + e;
  const T tail = 2.0 * e / one_plus_e;
  return {sign, tail, sign * (1.0 - tail), 4.0 * e / (one_plus_e * one_plus_e)};
}

// Contribution of one regularised transition to F..F''' (eq. 3.19 summand, with 3.18).
template <class T, class S>
void add_transition(const Transition<S>& tr, int periodic_terms, const T& theta, RollingContact<T>& out) {
  const T a = theta - T(tr.angle);
  const T k = T(tr.k);
  const T half_a_sin = sin(0.5 * a);
  // g = k^2 + 1 - cos(a) and its derivatives
  const T g = k * k + 2.0 * half_a_sin * half_a_sin;
  const T g1 = sin(a);
  const T g2 = cos(a);
  const T g3 = -g1;
  // H = 1 + tanh(a/k) + periodic pairs; H1..H3 its derivatives in theta
  double step = 1.0;
  T tails = T(0.0);
  T H1 = T(0.0), H2 = T(0.0), H3 = T(0.0);
  const T inv_k = 1.0 / k;
  auto accumulate = [&](const T& shifted) {
    const TanhTerm<T> tt = tanh_term(T(shifted * inv_k));
    step += tt.sign;
    tails -= tt.sign * tt.tail;
    H1 += tt.s * inv_k;
    H2 += -2.0 * tt.t * tt.s * inv_k * inv_k;
    H3 += 2.0 * tt.s * (3.0 * tt.t * tt.t - 1.0) * inv_k * inv_k * inv_k;
  };
  accumulate(a);
  for (int n = 1; n <= periodic_terms; ++n) {
    accumulate(T(a - 2.0 * std::numbers::pi * n));
    accumulate(T(a + 2.0 * std::numbers::pi * n));
  }
  const T H = step + tails;
  const T half_l = 0.5 * T(tr.length);
  out.F += half_l * g * H;
  out.dF += half_l * (g1 * H + g * H1);
  out.ddF += half_l * (g2 * H + 2.0 * g1 * H1 + g * H2);
  out.dddF += half_l * (g3 * H + 3.0 * g2 * H1 + 3.0 * g1 * H2 + g * H3);
}

// The sign-determining bracket of eq. (3.14) / (A.1) for one tanh term at a = theta - delta:
// (2cos a - 1 + k^2 + 6 tanh^2) - 6/k sin a tanh - (1 - cos a)(2 - 6 tanh^2)/k^2.
// Appendix A proves it positive for every real a and k > 0.
template <class T>
T convexity_bracket(const T& a, const T& k, const T& t) {
  const T half_a_sin = sin(0.5 * a);
  const T one_minus_cos = 2.0 * half_a_sin * half_a_sin;
  const T t2 = t * t;
  return (2.0 * cos(a) - 1.0 + k * k + 6.0 * t2) - 6.0 / k * sin(a) * t - one_minus_cos * (2.0 - 6.0 * t2) / (k * k);
}

// Closed-form curvature radius of one tanh term of a transition, eq. (3.14):
// l/(2k) sech^2(a/k) * convexity_bracket(a, k).
template <class T, class S>
T curvature_radius_term(const Transition<S>& tr, const T& a) {
  const T k = T(tr.k);
  const TanhTerm<T> tt = tanh_term(T(a / k));
  return T(tr.length) / (2.0 * k) * tt.s * convexity_bracket(a, k, tt.t);
}

// Length sqrt(x^2 + z^2) and direction atan2(z, x) of a polygon edge. An edge that vanishes (the
// polygon degenerating at the ankle: h_F -> 0 together with l_HA -> 0 or l_HM - l_HA -> 0, the
// "stilt" of seed 001 section 10.2) has length 0 and a constant direction (that of +x, which it
// has in the limit z = 0, x -> 0+), so no 0/0 enters the derivatives; it contributes nothing to F.
template <class S>
std::pair<S, S> edge_length_and_direction(const S& z, const S& x) {
  using std::atan2, std::sqrt;
  using ad::atan2;
  if (ad::value(z) == 0.0 && ad::value(x) == 0.0) return {S(0.0), S(0.0)};
  return {sqrt(z * z + x * x), atan2(z, x)};
}

}  // namespace detail

// Builds the profile of a foot model from its parameter vector (eq. 3.20, 3.23). Validation of
// the values is the job of foot_spec.hpp; this function only does the geometry.
template <class S>
FootProfile<S> make_profile(FootModel model, const FootParameters<S>& p, int periodic_terms = 0) {
  using std::atan2, std::cos, std::sin, std::sqrt;
  using ad::atan2;
  constexpr double pi = std::numbers::pi;
  FootProfile<S> prof;
  prof.model = model;
  prof.periodic_terms = periodic_terms;
  switch (model) {
    case FootModel::point:
      prof.transition_count = 0;
      break;
    case FootModel::hm: {
      const S h = p[hm::h_F], a = p[hm::l_HA], l = p[hm::l_HM];
      const S b = l - a;  // ankle projection to M
      const auto [heel, heel_angle] = detail::edge_length_and_direction(h, a);
      const auto [front, front_angle] = detail::edge_length_and_direction(h, b);
      prof.transitions[0] = {heel, S(-pi) + heel_angle, p[hm::k_H]};    // (3.20a)
      prof.transitions[1] = {l, S(0.0), p[hm::k_HM]};                   // (3.20b)
      prof.transitions[2] = {front, S(pi) - front_angle, p[hm::k_M]};   // (3.20c)
      prof.transition_count = 3;
      break;
    }
    case FootModel::hmt: {
      const S h = p[hmt::h_F], a = p[hmt::l_HA], l = p[hmt::l_HM], lt = p[hmt::l_MT], g = p[hmt::gamma_F];
      const S tz = h - lt * sin(g);        // depth of the toe tip T below the ankle
      const S tx = l - a + lt * cos(g);    // forward distance of T from the ankle
      const auto [heel, heel_angle] = detail::edge_length_and_direction(h, a);
      const auto [front, front_angle] = detail::edge_length_and_direction(tz, tx);
      prof.transitions[0] = {heel, S(-pi) + heel_angle, p[hmt::k_H]};  // (3.23a)
      prof.transitions[1] = {l, S(0.0), p[hmt::k_HM]};                 // (3.23b)
      prof.transitions[2] = {lt, g, p[hmt::k_MT]};                     // (3.23c)
      prof.transitions[3] = {front, S(pi) - front_angle, p[hmt::k_T]};  // (3.23d)
      prof.transition_count = 4;
      break;
    }
  }
  if (prof.transition_count > 0) {
    prof.theta_min = prof.transitions[0].angle;
    prof.theta_max = prof.transitions[prof.transition_count - 1].angle;
  }
  return prof;
}

// F, F', F'', F''' at theta (eq. 3.19 / 3.22, optionally with the terms of eq. 3.18).
template <class T, class S>
RollingContact<T> rolling_contact(const FootProfile<S>& prof, const T& theta) {
  RollingContact<T> out{T(0.0), T(0.0), T(0.0), T(0.0)};
  for (int i = 0; i < prof.transition_count; ++i) detail::add_transition(prof.transitions[i], prof.periodic_terms, theta, out);
  return out;
}

// Curvature radius R(theta) = F' + F''' (eq. 2.34, 3.10c), summed term by term from eq. (3.14).
// Non-negative by construction; it underflows to 0 only where the exact value is below ~1e-300 m.
template <class T, class S>
T curvature_radius(const FootProfile<S>& prof, const T& theta) {
  T r = T(0.0);
  for (int i = 0; i < prof.transition_count; ++i) {
    const Transition<S>& tr = prof.transitions[i];
    const T a = theta - T(tr.angle);
    r += detail::curvature_radius_term(tr, a);
    for (int n = 1; n <= prof.periodic_terms; ++n) {
      r += detail::curvature_radius_term(tr, T(a - 2.0 * std::numbers::pi * n));
      r += detail::curvature_radius_term(tr, T(a + 2.0 * std::numbers::pi * n));
    }
  }
  return r;
}

}  // namespace cyclopt::foot
