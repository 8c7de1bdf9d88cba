#pragma once
// Tangent<T>: a value and one directional derivative, both of scalar type T. Unlike Dual<N> (whose
// parts are doubles) it nests: Tangent<Dual<N>> carries a derivative along one extra direction
// whose own N first derivatives are exact - mixed second derivatives from first-order code. The
// giant-swing zero dynamics use it for d/dphi along the motion (the jerk alpha''') inside an NLP
// whose gradient comes from Dual<N>.

#include "cyclopt/autodiff/dual.hpp"

#include <Eigen/Core>

#include <cmath>

namespace cyclopt::ad {

template <class T>
struct Tangent {
  T v{};
  T d{};
  Tangent() = default;
  Tangent(const T& value) : v(value), d(0.0) {}  // NOLINT: constants mix freely
  Tangent(double value) requires(!std::is_same_v<T, double>) : v(value), d(0.0) {}  // NOLINT
  Tangent(const T& value, const T& derivative) : v(value), d(derivative) {}

  Tangent& operator+=(const Tangent& o) { v += o.v; d += o.d; return *this; }
  Tangent& operator-=(const Tangent& o) { v -= o.v; d -= o.d; return *this; }
  Tangent& operator*=(const Tangent& o) { d = d * o.v + v * o.d; v *= o.v; return *this; }
  Tangent& operator/=(const Tangent& o) { v /= o.v; d = (d - v * o.d) / o.v; return *this; }
};

template <class T> double value(const Tangent<T>& x) { return value(x.v); }

template <class T> Tangent<T> operator+(const Tangent<T>& a) { return a; }
template <class T> Tangent<T> operator-(const Tangent<T>& a) { return Tangent<T>(-a.v, -a.d); }
template <class T> Tangent<T> operator+(Tangent<T> a, const Tangent<T>& b) { return a += b; }
template <class T> Tangent<T> operator-(Tangent<T> a, const Tangent<T>& b) { return a -= b; }
template <class T> Tangent<T> operator*(Tangent<T> a, const Tangent<T>& b) { return a *= b; }
template <class T> Tangent<T> operator/(Tangent<T> a, const Tangent<T>& b) { return a /= b; }
template <class T> Tangent<T> operator+(Tangent<T> a, double c) { a.v += c; return a; }
template <class T> Tangent<T> operator-(Tangent<T> a, double c) { a.v -= c; return a; }
template <class T> Tangent<T> operator*(const Tangent<T>& a, double c) { return Tangent<T>(a.v * c, a.d * c); }
template <class T> Tangent<T> operator/(const Tangent<T>& a, double c) { return Tangent<T>(a.v / c, a.d / c); }
template <class T> Tangent<T> operator+(double c, Tangent<T> a) { a.v += c; return a; }
template <class T> Tangent<T> operator-(double c, const Tangent<T>& a) { return Tangent<T>(c - a.v, -a.d); }
template <class T> Tangent<T> operator*(double c, const Tangent<T>& a) { return Tangent<T>(c * a.v, c * a.d); }
template <class T> Tangent<T> operator/(double c, const Tangent<T>& a) { return Tangent<T>(c) / a; }

template <class T> bool operator<(const Tangent<T>& a, double b) { return value(a) < b; }
template <class T> bool operator>(const Tangent<T>& a, double b) { return value(a) > b; }
template <class T> bool operator>=(const Tangent<T>& a, double b) { return value(a) >= b; }
template <class T> bool operator<=(const Tangent<T>& a, double b) { return value(a) <= b; }

template <class T> Tangent<T> sin(const Tangent<T>& a) {
  using std::cos;
  using std::sin;
  return Tangent<T>(sin(a.v), cos(a.v) * a.d);
}
template <class T> Tangent<T> cos(const Tangent<T>& a) {
  using std::cos;
  using std::sin;
  return Tangent<T>(cos(a.v), -(sin(a.v) * a.d));
}
template <class T> Tangent<T> sqrt(const Tangent<T>& a) {
  using std::sqrt;
  const T s = sqrt(a.v);
  return Tangent<T>(s, a.d / (2.0 * s));
}

}  // namespace cyclopt::ad

namespace Eigen {
template <class T>
struct NumTraits<cyclopt::ad::Tangent<T>> : NumTraits<double> {
  using Real = cyclopt::ad::Tangent<T>;
  using NonInteger = cyclopt::ad::Tangent<T>;
  using Nested = cyclopt::ad::Tangent<T>;
  using Literal = double;
  enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 1, ReadCost = 2, AddCost = 2, MulCost = 4 };
};
template <class T, typename BinaryOp>
struct ScalarBinaryOpTraits<cyclopt::ad::Tangent<T>, double, BinaryOp> { using ReturnType = cyclopt::ad::Tangent<T>; };
template <class T, typename BinaryOp>
struct ScalarBinaryOpTraits<double, cyclopt::ad::Tangent<T>, BinaryOp> { using ReturnType = cyclopt::ad::Tangent<T>; };
}  // namespace Eigen
