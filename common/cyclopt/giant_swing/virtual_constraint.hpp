#pragma once
// Part B parametrisation: the hip angle as a virtual constraint alpha = b(phi) with phi as the
// phase variable, b a Bezier polynomial of degree m = n + 5 in s = phi / 2 pi (wrapped to [0, 1] for
// a sequence of swings), n = 4..12 free coefficients. The first three and last three coefficients
// are zero, so alpha = alpha' = alpha'' = 0 in the handstand at both ends (seed 000, eq. 3.10-3.11,
// and a C^2-periodic continuation) for every n. By the convex-hull property, coefficient bounds
// [-pi/4, pi/2] keep alpha in the admissible range of ch. 4.2.
//
// On the constraint alpha'' = b' phi'' + b'' phi'^2. The first row of M q'' = h + (M_R, M_alpha)
// (the angular-momentum balance 3.5, free of M_alpha) then gives
//   (M11 + M12 b') phi'' = h1 - M12 c + M_R,   c = b'' phi'^2 (+ feedback terms),
// with M_R again the root of M_R = -k |u + v M_R| (A.69); the second row gives the hip torque
// M_alpha (eq. 3.9) that enforces the constraint.

#include "cyclopt/giant_swing/hip_torque_law.hpp"

#include <Eigen/Core>

#include <array>
#include <cmath>

namespace cyclopt::giant_swing {

inline constexpr int kMinFreeBezierCoefficients = 4;
inline constexpr int kMaxFreeBezierCoefficients = 12;
inline constexpr int kMaxBezierDegree = kMaxFreeBezierCoefficients + 5;

// c0..cm, m = degree; storage on the stack (at most kMaxBezierDegree + 1 entries).
template <class T>
using BezierCoefficients = Eigen::Matrix<T, Eigen::Dynamic, 1, 0, kMaxBezierDegree + 1, 1>;

// Full coefficient vector from the n free ones c3..c(n+2) (c0 = c1 = c2 = 0 = the last three).
template <class Derived>
BezierCoefficients<typename Derived::Scalar> bezier_from_free(const Eigen::MatrixBase<Derived>& free) {
  using T = typename Derived::Scalar;
  const int n = int(free.size());
  BezierCoefficients<T> c(n + 6);
  for (int i = 0; i < n + 6; ++i) c[i] = T(0.0);
  for (int i = 0; i < n; ++i) c[i + 3] = free[i];
  return c;
}

// b and its first three derivatives with respect to phi: {b, db/dphi, d2b/dphi2, d3b/dphi3}.
template <class R, class C, class S>
std::array<R, 4> bezier_hip_angle(const BezierCoefficients<C>& coefficients, const S& phi) {
  const S u = phi / kTwoPi;
  // Wrap into [0, 1] for a sequence of swings; phi = 2 pi itself stays at s = 1 (end of the swing).
  const double shift = ad::value(u) >= 0.0 && ad::value(u) <= 1.0 ? 0.0 : std::floor(ad::value(u));
  const S s = u - shift;
  const int degree = int(coefficients.size()) - 1;
  std::array<R, 4> out;
  std::array<C, kMaxBezierDegree + 1> diff{};
  for (int i = 0; i <= degree; ++i) diff[static_cast<std::size_t>(i)] = coefficients[i];
  double factor = 1.0;  // m!/(m-k)! / (2 pi)^k
  for (int k = 0; k < 4; ++k) {
    const int m = degree - k;
    std::array<R, kMaxBezierDegree + 1> work{};  // de Casteljau on the k-th differences
    for (int i = 0; i <= m; ++i) work[static_cast<std::size_t>(i)] = R(diff[static_cast<std::size_t>(i)]);
    for (int r = 1; r <= m; ++r)
      for (int i = 0; i <= m - r; ++i)
        work[static_cast<std::size_t>(i)] =
            (1.0 - s) * work[static_cast<std::size_t>(i)] + s * work[static_cast<std::size_t>(i + 1)];
    out[static_cast<std::size_t>(k)] = factor * work[0];
    for (int i = 0; i < m; ++i)
      diff[static_cast<std::size_t>(i)] = diff[static_cast<std::size_t>(i + 1)] - diff[static_cast<std::size_t>(i)];
    factor *= double(m) / kTwoPi;
  }
  return out;
}

template <class T>
struct ConstrainedAccelerations {
  T phi_acceleration;
  T alpha_acceleration;
  T friction_moment;
  T hip_torque;
};

// Accelerations and hip torque when alpha'' = slope * phi'' + offset is imposed (slope = b').
template <class T>
ConstrainedAccelerations<T> constrained_accelerations(const Model& model, const State<T>& x, const T& slope,
                                                      const T& offset) {
  const Matrix2<T> M = mass_matrix(model, x[1]);
  const Vector2<T> h = bias_forces(model, x);
  const T inertia = M(0, 0) + M(0, 1) * slope;
  const T free_part = h[0] - M(0, 1) * offset;
  ConstrainedAccelerations<T> out;
  const double k = model.bar_radius * model.friction_coefficient;
  out.friction_moment = T(0.0);
  if (k != 0.0) {
    const CentreOfMassAcceleration<T> com = centre_of_mass_acceleration(model, x);
    const Vector2<T> direction = com.A.col(0) + com.A.col(1) * slope;  // d(m a_sp)/d phi''
    const Vector2<T> u = direction * (free_part / inertia) + com.A.col(1) * offset + com.c +
                         Vector2<T>(T(0.0), T(model.total_mass() * model.g));
    const Vector2<T> v = direction / inertia;
    out.friction_moment = solve_friction_moment(k, ad::value(x[2]) >= 0.0 ? 1.0 : -1.0, u, v);
  }
  out.phi_acceleration = (free_part + out.friction_moment) / inertia;
  out.alpha_acceleration = slope * out.phi_acceleration + offset;
  out.hip_torque = M(1, 0) * out.phi_acceleration + M(1, 1) * out.alpha_acceleration - h[1];
  return out;
}

// Hip torque law enforcing alpha = b(phi) with error dynamics e'' + kd e' + kp e = 0
// (e = alpha - b(phi)): the stabilising feedback the seed asks for in ch. 5.2 (eq. 5.3-5.4).
// Default gains: a double pole of the error dynamics at -20/s.
inline constexpr double kConstraintGainP = 400.0;  // 1/s^2
inline constexpr double kConstraintGainD = 40.0;   // 1/s
class VirtualConstraintTorque : public HipTorqueLawOf<VirtualConstraintTorque> {
 public:
  VirtualConstraintTorque(BezierCoefficients<double> coefficients, double kp, double kd, const Model& model)
      : coefficients_(std::move(coefficients)), kp_(kp), kd_(kd), model_(model) {}

  template <class T>
  T torque(const State<T>& x) const {
    const std::array<T, 4> b = bezier_hip_angle<T>(coefficients_, x[0]);
    const T e = x[1] - b[0];
    const T e_rate = x[3] - b[1] * x[2];
    const T offset = b[2] * x[2] * x[2] - kp_ * e - kd_ * e_rate;
    return constrained_accelerations(model_, x, b[1], offset).hip_torque;
  }

 private:
  BezierCoefficients<double> coefficients_;
  double kp_, kd_;
  Model model_;
};

}  // namespace cyclopt::giant_swing
