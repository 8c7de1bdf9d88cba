#pragma once
// Scalar-type utilities shared by every template in common/: the real value of a scalar (for
// branching and validation) and a conversion between scalar types.

#include "cyclopt/autodiff/dual.hpp"

#include <complex>

namespace cyclopt::ad {

// The real part that decides branches: x for double, x.v for Dual, x.real() for complex.
template <class T>
double value(const std::complex<T>& x) { return value(x.real()); }

// Converts a double-valued constant into scalar type T (a constant: zero derivative part).
template <class T>
T constant(double x) { return T(x); }

}  // namespace cyclopt::ad
