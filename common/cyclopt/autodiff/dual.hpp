#pragma once
// Forward-mode automatic differentiation with a fixed number of directions.
//
// Dual<N> carries a value v and N directional derivatives d. Every numerical routine in
// common/ is templated on its scalar type, so instantiating it with Dual<N> yields exact first
// derivatives (no truncation error) from the same code that computes values. Jacobians wider than
// N are assembled in chunks of N seed directions (see jacobian.hpp).
//
// The seed's own derivative method (chapter 6.1) is the complex step; std::complex<double> works
// with the same templates and is used by the tests as an independent check.

#include <Eigen/Core>

#include <cmath>
#include <ostream>
#include <type_traits>

namespace cyclopt::ad {

template <int N>
struct Dual {
  static_assert(N > 0, "Dual<N> needs a fixed, positive number of directions");
  using Gradient = Eigen::Matrix<double, N, 1>;

  double v = 0.0;
  Gradient d = Gradient::Zero();

  Dual() = default;
  Dual(double value) : v(value) {}  // NOLINT: implicit, constants mix freely with duals
  Dual(double value, const Gradient& grad) : v(value), d(grad) {}

  // A variable: value with unit derivative in direction `direction`.
  static Dual variable(double value, int direction) {
    Dual x(value);
    x.d[direction] = 1.0;
    return x;
  }

  Dual& operator+=(const Dual& o) { v += o.v; d += o.d; return *this; }
  Dual& operator-=(const Dual& o) { v -= o.v; d -= o.d; return *this; }
  Dual& operator*=(const Dual& o) { d = d * o.v + v * o.d; v *= o.v; return *this; }
  Dual& operator/=(const Dual& o) {
    const double inv = 1.0 / o.v;
    v *= inv;
    d = (d - v * o.d) * inv;
    return *this;
  }
  Dual& operator+=(double c) { v += c; return *this; }
  Dual& operator-=(double c) { v -= c; return *this; }
  Dual& operator*=(double c) { v *= c; d *= c; return *this; }
  Dual& operator/=(double c) { v /= c; d /= c; return *this; }
};

// True for Dual<N> (lets templated code take shortcuts that need plain double derivative parts).
template <class T>
struct is_dual : std::false_type {};
template <int N>
struct is_dual<Dual<N>> : std::true_type {};
template <class T>
inline constexpr bool is_dual_v = is_dual<T>::value;

// The value part of any scalar: identity for double, .v for Dual.
inline double value(double x) { return x; }
template <int N>
double value(const Dual<N>& x) { return x.v; }

template <int N> Dual<N> operator+(const Dual<N>& a) { return a; }
template <int N> Dual<N> operator-(const Dual<N>& a) { return Dual<N>(-a.v, -a.d); }

template <int N> Dual<N> operator+(Dual<N> a, const Dual<N>& b) { return a += b; }
template <int N> Dual<N> operator-(Dual<N> a, const Dual<N>& b) { return a -= b; }
template <int N> Dual<N> operator*(Dual<N> a, const Dual<N>& b) { return a *= b; }
template <int N> Dual<N> operator/(Dual<N> a, const Dual<N>& b) { return a /= b; }

template <int N> Dual<N> operator+(Dual<N> a, double c) { return a += c; }
template <int N> Dual<N> operator-(Dual<N> a, double c) { return a -= c; }
template <int N> Dual<N> operator*(Dual<N> a, double c) { return a *= c; }
template <int N> Dual<N> operator/(Dual<N> a, double c) { return a /= c; }
template <int N> Dual<N> operator+(double c, Dual<N> a) { return a += c; }
template <int N> Dual<N> operator-(double c, const Dual<N>& a) { return Dual<N>(c - a.v, -a.d); }
template <int N> Dual<N> operator*(double c, Dual<N> a) { return a *= c; }
template <int N> Dual<N> operator/(double c, const Dual<N>& a) {
  const double inv = 1.0 / a.v;
  return Dual<N>(c * inv, (-c * inv * inv) * a.d);
}

// Comparisons look at the value only (branches in the model are taken on values).
#define CYCLOPT_DUAL_COMPARE(op)                                                        \
  template <int N> bool operator op(const Dual<N>& a, const Dual<N>& b) { return a.v op b.v; } \
  template <int N> bool operator op(const Dual<N>& a, double b) { return a.v op b; }           \
  template <int N> bool operator op(double a, const Dual<N>& b) { return a op b.v; }
CYCLOPT_DUAL_COMPARE(<)
CYCLOPT_DUAL_COMPARE(>)
CYCLOPT_DUAL_COMPARE(<=)
CYCLOPT_DUAL_COMPARE(>=)
CYCLOPT_DUAL_COMPARE(==)
CYCLOPT_DUAL_COMPARE(!=)
#undef CYCLOPT_DUAL_COMPARE

// Chain rule for a scalar function: f(a) = fa, f'(a) = dfa.
template <int N> Dual<N> chain(const Dual<N>& a, double fa, double dfa) { return Dual<N>(fa, dfa * a.d); }

template <int N> Dual<N> sin(const Dual<N>& a) { return chain(a, std::sin(a.v), std::cos(a.v)); }
template <int N> Dual<N> cos(const Dual<N>& a) { return chain(a, std::cos(a.v), -std::sin(a.v)); }
template <int N> Dual<N> tan(const Dual<N>& a) {
  const double t = std::tan(a.v);
  return chain(a, t, 1.0 + t * t);
}
template <int N> Dual<N> tanh(const Dual<N>& a) {
  const double t = std::tanh(a.v);
  return chain(a, t, 1.0 - t * t);
}
template <int N> Dual<N> sinh(const Dual<N>& a) { return chain(a, std::sinh(a.v), std::cosh(a.v)); }
template <int N> Dual<N> cosh(const Dual<N>& a) { return chain(a, std::cosh(a.v), std::sinh(a.v)); }
template <int N> Dual<N> exp(const Dual<N>& a) {
  const double e = std::exp(a.v);
  return chain(a, e, e);
}
template <int N> Dual<N> log(const Dual<N>& a) { return chain(a, std::log(a.v), 1.0 / a.v); }
template <int N> Dual<N> sqrt(const Dual<N>& a) {
  const double s = std::sqrt(a.v);
  return chain(a, s, 0.5 / s);
}
template <int N> Dual<N> atan(const Dual<N>& a) { return chain(a, std::atan(a.v), 1.0 / (1.0 + a.v * a.v)); }
template <int N> Dual<N> asin(const Dual<N>& a) {
  return chain(a, std::asin(a.v), 1.0 / std::sqrt(1.0 - a.v * a.v));
}
template <int N> Dual<N> acos(const Dual<N>& a) {
  return chain(a, std::acos(a.v), -1.0 / std::sqrt(1.0 - a.v * a.v));
}
template <int N> Dual<N> abs(const Dual<N>& a) { return a.v < 0.0 ? -a : a; }
template <int N> Dual<N> pow(const Dual<N>& a, double p) {
  const double ap = std::pow(a.v, p);
  return chain(a, ap, p * std::pow(a.v, p - 1.0));
}
template <int N> Dual<N> atan2(const Dual<N>& y, const Dual<N>& x) {
  const double r2 = x.v * x.v + y.v * y.v;
  return Dual<N>(std::atan2(y.v, x.v), (x.v * y.d - y.v * x.d) / r2);
}
template <int N> Dual<N> atan2(const Dual<N>& y, double x) { return atan2(y, Dual<N>(x)); }
template <int N> Dual<N> atan2(double y, const Dual<N>& x) { return atan2(Dual<N>(y), x); }
template <int N> Dual<N> hypot(const Dual<N>& a, const Dual<N>& b) { return sqrt(a * a + b * b); }
template <int N> bool isfinite(const Dual<N>& a) { return std::isfinite(a.v) && a.d.allFinite(); }
template <int N> bool isnan(const Dual<N>& a) { return std::isnan(a.v) || a.d.hasNaN(); }

template <int N>
std::ostream& operator<<(std::ostream& os, const Dual<N>& a) {
  return os << a.v << " [" << a.d.transpose() << "]";
}

}  // namespace cyclopt::ad

namespace Eigen {
// Lets Eigen matrices hold Dual<N> (products, decompositions).
template <int N>
struct NumTraits<cyclopt::ad::Dual<N>> : NumTraits<double> {
  using Real = cyclopt::ad::Dual<N>;
  using NonInteger = cyclopt::ad::Dual<N>;
  using Nested = cyclopt::ad::Dual<N>;
  using Literal = double;
  enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 1,
         ReadCost = N + 1, AddCost = N + 1, MulCost = 2 * N + 1 };
};
template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<cyclopt::ad::Dual<N>, double, BinaryOp> { using ReturnType = cyclopt::ad::Dual<N>; };
template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<double, cyclopt::ad::Dual<N>, BinaryOp> { using ReturnType = cyclopt::ad::Dual<N>; };
}  // namespace Eigen
