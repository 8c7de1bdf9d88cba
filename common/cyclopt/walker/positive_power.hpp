#pragma once
// f_mech's integrand max(p, 0) of a joint power p = u q_dot (seed 001 eq. 5.100) over one interval
// of the trapezoid rule in time, p linear between the grid values p0 and p1:
//
//   positive_part_trapezoid: the seed's rule, the zero crossing located by linear interpolation
//     (Fig. 5.3). Exact for the linear p, continuously differentiable in (p0, p1) except at
//     p0 = p1 = 0, where it is |.|-like.
//   rounded_positive_part_trapezoid: the same integral of the positive part rounded on the band
//     |p| < e,  s(p) = (p + e)^2 / (4 e)  there (s = max(p, 0) outside, C1), integrated exactly.
//     Equal to the seed's rule on every interval where |p| >= e throughout.
//   smoothed_positive_part_trapezoid: the same integral of the smooth positive part
//     s(p) = (p + sqrt(p^2 + e^2)) / 2 (C-infinity, s - max(p, 0) <= e/2, largest at p = 0), integrated
//     exactly; it tends to the seed's rule as e -> 0. The integrand of the smoothing homotopy
//     (smoothing_homotopy.hpp).
//
// Why the band: a joint the optimum holds still (q_dot = 0 over the step, e.g. the stance ankle at
// 0.3 m/s) sits at the kink of max(u q_dot, 0) in the gait parameters: moving it either way costs
// positive work, the gradient there is one-sided, and the SQP's KKT test does not settle (runs crawl
// at KKT errors 1e-2..1, bench/results/walker_solvers.txt). Rounded, that minimum is smooth. The
// error is at most e/4 per joint where |p| < e: for a joint still over the whole step
// e / (4 m g v_bar) in f_mech (e = 1 mW, m = 80.16 kg, 0.3 m/s: 1.1e-6, against f_mech ~ 5e-3).

#include "cyclopt/autodiff/scalar.hpp"

#include <algorithm>
#include <cmath>

namespace cyclopt::walker {

template <class T>
T positive_part_trapezoid(const T& p0, const T& p1, const T& dt) {
  const double a = ad::value(p0), b = ad::value(p1);
  if (a >= 0.0 && b >= 0.0) return 0.5 * (p0 + p1) * dt;
  if (a <= 0.0 && b <= 0.0) return T(0.0);
  const T frac = p0 / (p0 - p1);  // crossing at t0 + frac dt
  return a > 0.0 ? T(0.5 * p0 * frac * dt) : T(0.5 * p1 * (1.0 - frac) * dt);
}

namespace detail {

// The pieces of the rounded positive part: 0 below -e, the parabola on the band, p above e.
enum class BandPiece { below = 0, inside = 1, above = 2 };

inline BandPiece band_piece(double p, double e) {
  return p <= -e ? BandPiece::below : (p >= e ? BandPiece::above : BandPiece::inside);
}

template <class T>
T rounded_positive_part(const T& p, double e, BandPiece piece) {
  if (piece == BandPiece::below) return T(0.0);
  if (piece == BandPiece::above) return p;
  return (p + e) * (p + e) / (4.0 * e);
}

}  // namespace detail

// band = e > 0 (the unit of p). The interval [0, 1] (in units of dt) is cut where the linear p
// crosses -e or e; on each piece s(p) is a polynomial of degree <= 2 in time, which Simpson's rule
// integrates exactly. The cut points depend on (p0, p1) but s is continuous there, so their
// derivatives cancel: the derivative of the sum is exact.
template <class T>
T rounded_positive_part_trapezoid(const T& p0, const T& p1, const T& dt, double band) {
  using detail::BandPiece;
  const BandPiece first = detail::band_piece(ad::value(p0), band), last = detail::band_piece(ad::value(p1), band);
  const int direction = last > first ? 1 : -1;
  T total = T(0.0), tau_left = T(0.0), p_left = p0;
  for (int k = static_cast<int>(first);; k += direction) {
    const BandPiece piece = static_cast<BandPiece>(k);
    T tau_right = T(1.0), p_right = p1;
    if (piece != last) {  // leave the piece through its edge towards `last`: -e between below and inside, else e
      const bool lower_edge = direction > 0 ? piece == BandPiece::below : piece == BandPiece::inside;
      const double edge = lower_edge ? -band : band;
      tau_right = (edge - p0) / (p1 - p0);
      p_right = T(edge);
    }
    const T p_mid = 0.5 * (p_left + p_right);
    total += (tau_right - tau_left) *
             (detail::rounded_positive_part(p_left, band, piece) + 4.0 * detail::rounded_positive_part(p_mid, band, piece) +
              detail::rounded_positive_part(p_right, band, piece)) /
             6.0;
    if (piece == last) break;
    tau_left = tau_right;
    p_left = p_right;
  }
  return total * dt;
}

namespace detail {

template <class T>
T smoothed_positive_part(const T& p, double e) { return 0.5 * (p + sqrt(p * p + e * e)); }

// G(p) = int_0^p s(q) dq = (p (p + r) + e^2 asinh(p/e)) / 4, r = sqrt(p^2 + e^2); for p < 0,
// p + r = e^2 / (r - p) without cancellation, and asinh is odd.
template <class T>
T smoothed_positive_part_antiderivative(const T& p, double e) {
  const T r = sqrt(p * p + e * e);
  const bool negative = ad::value(p) < 0.0;
  const T p_plus_r = negative ? T(e * e / (r - p)) : T(p + r);
  const T x = (negative ? T(-p) : p) / e;
  const T asinh_abs = log(x + sqrt(x * x + 1.0));
  return 0.25 * (p * p_plus_r + e * e * (negative ? T(-asinh_abs) : asinh_abs));
}

}  // namespace detail

// smoothing = e > 0 (the unit of p). The mean of s over the interval is (G(p1) - G(p0)) / (p1 - p0);
// where p changes by less than a tenth of max(|p0|, |p1|, e) that quotient loses digits, and the
// 5-point Gauss-Legendre rule is exact to rounding instead (s is analytic there: its singularities
// +-i e lie at least ten half-lengths of the interval away).
template <class T>
T smoothed_positive_part_trapezoid(const T& p0, const T& p1, const T& dt, double smoothing) {
  const double e = smoothing, a = ad::value(p0), b = ad::value(p1);
  const double scale = std::max({std::abs(a), std::abs(b), e});
  if (std::abs(b - a) >= 0.1 * scale)
    return (detail::smoothed_positive_part_antiderivative(p1, e) - detail::smoothed_positive_part_antiderivative(p0, e)) /
           (p1 - p0) * dt;
  static constexpr double node[5] = {0.0469100770306680, 0.2307653449471585, 0.5, 0.7692346550528415, 0.9530899229693320};
  static constexpr double weight[5] = {0.1184634425280945, 0.2393143352496832, 0.2844444444444444, 0.2393143352496832,
                                       0.1184634425280945};
  T mean = T(0.0);
  for (int k = 0; k < 5; ++k) mean += weight[k] * detail::smoothed_positive_part(T(p0 + node[k] * (p1 - p0)), e);
  return mean * dt;
}

}  // namespace cyclopt::walker
