#pragma once
// Scalar-type utilities shared by every template in common/: the real value of a scalar (for
// branching and validation), a conversion between scalar types, and the few functions the
// standard library lacks for std::complex (used by complex-step checks).

#include "cyclopt/autodiff/dual.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <utility>

namespace cyclopt::ad {

// The real part that decides branches: x for double, x.v for Dual, x.real() for complex.
template <class T>
double value(const std::complex<T>& x) { return value(x.real()); }

// The scalar of a computation mixing scalar types A and B (e.g. a double model with Dual gait
// parameters): Dual<N> for (double, Dual<N>), complex for (double, complex), A for (A, A).
template <class A, class B>
using promoted_t = std::decay_t<decltype(std::declval<A>() * std::declval<B>())>;

// Converts a double-valued constant into scalar type T (a constant: zero derivative part).
template <class T>
T constant(double x) { return T(x); }

// Bilinear dot product sum a_i b_i. Eigen's dot() conjugates complex arguments, which would break
// complex-step differentiation; templated model code uses this instead.
template <class A, class B>
auto dot(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  return a.cwiseProduct(b).sum();
}

// atan2 for complex arguments, holomorphic in a neighbourhood of real (y, x) off the branch cut:
// atan(y/x) plus the quadrant correction chosen from the real parts (or pi/2 - atan(x/y) near x = 0).
template <class T>
std::complex<T> atan2(const std::complex<T>& y, const std::complex<T>& x) {
  const double yr = value(y), xr = value(x);
  if (std::abs(xr) >= std::abs(yr)) {
    const std::complex<T> base = std::atan(y / x);
    if (xr >= 0.0) return base;
    return base + (yr >= 0.0 ? std::numbers::pi : -std::numbers::pi);
  }
  const std::complex<T> base = std::atan(x / y);
  return (yr >= 0.0 ? std::numbers::pi / 2 : -std::numbers::pi / 2) - base;
}

}  // namespace cyclopt::ad
