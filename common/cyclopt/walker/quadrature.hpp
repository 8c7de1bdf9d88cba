#pragma once
// Cumulative quadrature on the uniform phase grid of seed 001 eq. (5.93).
//
//   trapezoid (the seed's, footnote 11 of section 5.3):  I_k = h sum_{i<k} (f_i + f_{i+1}) / 2,   O(h^2)
//   corrected trapezoid (Euler-Maclaurin end correction): I_k - h^2/12 (f'_k - f'_0),             O(h^4)
//     with f' from second-order differences of the samples (central inside, one-sided at the ends),
//     so it needs no derivatives of the model and costs O(P) extra additions.
// The corrected rule is only valid for smooth integrands. For f_mech (5.100), whose integrand
// max(u q_dot, 0) has kinks where a joint power changes sign, the trapezoid rule keeps the seed's
// zero-crossing correction of Fig. 5.3 (O(h^2)); the corrected rule uses positive_part_integral
// below (O(h^4) for smooth powers: crossings located on a cubic, a cubic rule on each piece).

#include "cyclopt/walker/walker_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace cyclopt::walker {

enum class Quadrature { trapezoid, corrected_trapezoid };

// Running integrals I_0 = 0, ..., I_{P-1} of samples f on a grid with spacing h (P >= 3).
template <class T, class Samples>
Eigen::Matrix<T, Eigen::Dynamic, 1> cumulative_integral(const Samples& f, const T& h, Quadrature rule) {
  const int P = static_cast<int>(f.size());
  Eigen::Matrix<T, Eigen::Dynamic, 1> I(P);
  I(0) = T(0.0);
  for (int i = 1; i < P; ++i) I(i) = I(i - 1) + 0.5 * h * (f(i - 1) + f(i));
  if (rule == Quadrature::corrected_trapezoid && P >= 3) {
    auto slope = [&](int i) -> T {
      if (i == 0) return (-3.0 * f(0) + 4.0 * f(1) - f(2)) / (2.0 * h);
      if (i == P - 1) return (3.0 * f(P - 1) - 4.0 * f(P - 2) + f(P - 3)) / (2.0 * h);
      return (f(i + 1) - f(i - 1)) / (2.0 * h);
    };
    const T d0 = slope(0);
    for (int i = 1; i < P; ++i) I(i) -= h * h / 12.0 * (slope(i) - d0);
  }
  return I;
}

namespace detail {

// Coefficients (powers s^0..s^3) of the Lagrange basis on the nodes s = o, o+1, o+2, o+3.
inline std::array<std::array<double, 4>, 4> cubic_lagrange(int o) {
  std::array<std::array<double, 4>, 4> c{};
  for (int k = 0; k < 4; ++k) {
    std::array<double, 4> poly{1.0, 0.0, 0.0, 0.0};
    double denominator = 1.0;
    for (int m = 0; m < 4; ++m) {
      if (m == k) continue;
      for (int p = 3; p >= 1; --p) poly[p] = poly[p - 1] - (o + m) * poly[p];  // poly *= (s - (o + m))
      poly[0] *= -(o + m);
      denominator *= k - m;
    }
    for (int p = 0; p < 4; ++p) c[k][p] = poly[p] / denominator;
  }
  return c;
}

// The weight of sample k (its basis row Lk, powers s^0..s^3) in the integral of the cubic over [lo, hi].
inline double piece_weight(const std::array<double, 4>& Lk, double lo, double hi) {
  double w = 0.0;
  for (std::size_t p = 0; p < 4; ++p) {
    const double e = static_cast<double>(p + 1);
    w += Lk[p] * (std::pow(hi, e) - std::pow(lo, e)) / e;
  }
  return w;
}

}  // namespace detail

// Integral of max(g, 0) over [theta_0, theta_{P-1}] for samples g_0..g_{P-1} on a uniform grid with
// spacing h (P >= 4). On interval [i, i+1] the cubic c through the four nearest samples (i-1..i+2,
// one-sided at the ends) stands for g; if g_i and g_{i+1} have the same sign the interval adds
// int c (or nothing), else the root tau of c in (0, 1) is located in double by bisection and the
// positive piece of int c is added. The piece's weights are taken at the double tau: since
// c(tau) = 0, d/dg int_0^tau c = int_0^tau dc/dg exactly, so the derivative of this rule is exact.
// The rule is linear in g with these double weights, so they are summed per sample first and the
// integral is one product per sample (for a Dual g: one scaled derivative vector per sample, not
// four per interval).
template <class T, class Samples>
T positive_part_integral(const Samples& g, const T& h) {
  using Basis = std::array<std::array<double, 4>, 4>;
  static const std::array<Basis, 3> basis{detail::cubic_lagrange(0), detail::cubic_lagrange(-1), detail::cubic_lagrange(-2)};
  // The weights of a whole interval (the piece [0, 1]) per stencil position.
  static const std::array<std::array<double, 4>, 3> whole = [] {
    std::array<std::array<double, 4>, 3> w{};
    for (std::size_t b = 0; b < 3; ++b)
      for (std::size_t k = 0; k < 4; ++k) w[b][k] = detail::piece_weight(basis[b][k], 0.0, 1.0);
    return w;
  }();
  const int P = static_cast<int>(g.size());
  if (P < 4) throw std::invalid_argument("positive_part_integral: needs P >= 4 grid points");
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(P);
  for (int i = 0; i + 1 < P; ++i) {
    const int first = std::clamp(i - 1, 0, P - 4);  // stencil first..first+3, nodes at s = first - i ..
    const std::size_t position = static_cast<std::size_t>(i - first);
    const Basis& L = basis[position];
    const double a = ad::value(g(i)), b = ad::value(g(i + 1));
    if (a <= 0.0 && b <= 0.0) continue;
    if (a >= 0.0 && b >= 0.0) {
      for (int k = 0; k < 4; ++k) weight(first + k) += whole[position][static_cast<std::size_t>(k)];
      continue;
    }
    auto c = [&](double s) {
      double v = 0.0;
      for (int k = 0; k < 4; ++k)
        v += ad::value(g(first + k)) * (L[k][0] + s * (L[k][1] + s * (L[k][2] + s * L[k][3])));
      return v;
    };
    double left = 0.0, right = 1.0;  // c(left) has the sign of a
    for (int it = 0; it < 60 && right - left > 1e-15; ++it) {
      const double mid = 0.5 * (left + right);
      (c(mid) > 0.0) == (a > 0.0) ? left = mid : right = mid;
    }
    const double tau = 0.5 * (left + right);
    const double lo = a > 0.0 ? 0.0 : tau, hi = a > 0.0 ? tau : 1.0;  // the positive piece [lo, hi] in s
    for (int k = 0; k < 4; ++k) weight(first + k) += detail::piece_weight(L[static_cast<std::size_t>(k)], lo, hi);
  }
  T sum = T(0.0);
  for (int i = 0; i < P; ++i)
    if (weight(i) != 0.0) sum += weight(i) * g(i);
  return sum * h;
}

}  // namespace cyclopt::walker
