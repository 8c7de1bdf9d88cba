#pragma once
// Equations of motion of the two-segment gymnast (seed 000, eq. 3.2 / A.59), friction moment
// (eq. 3.3, A.66-A.69), templated on the scalar (double, ad::Dual<N>, std::complex<double>).
//
// Derivation (Lagrange, generalised coordinates q = (phi, alpha), psi = phi + alpha). With the bar
// at the origin and y up, the centres of mass are
//   r1 = S1 (sin phi, cos phi),   r2 = L1 (sin phi, cos phi) + S2 (sin psi, cos psi)    (A.30-A.41)
// so, with the constants Theta1, Theta2, chi1..chi3 of (3.1),
//   T = 1/2 Theta1 phi'^2 + 1/2 Theta2 psi'^2 + chi1 cos(alpha) phi' psi',
//   V = g (chi2 cos phi + chi3 cos psi).
// The hip torque M_alpha does virtual work M_alpha d(alpha), the bar friction M_R d(phi), hence
//   d/dt dT/dphi'   - dT/dphi   + dV/dphi   = M_R,
//   d/dt dT/dalpha' - dT/dalpha + dV/dalpha = M_alpha,
// i.e. M(alpha) q'' = h(q, q') + (M_R, M_alpha) with the symmetric mass matrix
//   M = [[Theta1 + Theta2 + 2 chi1 cos a,  Theta2 + chi1 cos a], [Theta2 + chi1 cos a,  Theta2]]
//   h = (chi1 sin a alpha' (2 phi' + alpha') + g (chi2 sin phi + chi3 sin psi),
//        -chi1 sin a phi'^2 + g chi3 sin psi).
// The first row is the balance of total angular momentum (3.4)-(3.5); the second row is (A.58);
// first minus second row gives (A.57). So this is the seed's (3.2), written symmetrically.
//
// Friction (A.65-A.69): M_R = -sign(phi') r mu |F| with the bar reaction
// F = (m1 + m2)(a_sp + g e_y) (A.66). F is linear in q'' and q'' is linear in M_R, so
// F = u + v M_R, and M_R = -s k |u + v M_R| (k = r mu) is a quadratic equation in M_R; we take
// its root of the right sign. This replaces the seed's lagged approximation (A.70) by the exact
// solution, keeping the right-hand side a smooth function of the state (needed for exact
// derivatives and for Floquet multipliers).

#include "cyclopt/autodiff/scalar.hpp"
#include "cyclopt/giant_swing/model.hpp"

#include <Eigen/Core>

#include <cmath>

namespace cyclopt::giant_swing {

// (phi, alpha, phi', alpha')
template <class T>
using State = Eigen::Matrix<T, 4, 1>;
template <class T>
using Vector2 = Eigen::Matrix<T, 2, 1>;
template <class T>
using Matrix2 = Eigen::Matrix<T, 2, 2>;

namespace state_index {
inline constexpr int phi = 0, alpha = 1, phi_rate = 2, alpha_rate = 3;
}

template <class T>
Matrix2<T> mass_matrix(const Model& model, const T& alpha) {
  using std::cos;
  const InertiaConstants c = inertia_constants(model);
  const T coupling = c.chi1 * cos(alpha);
  Matrix2<T> M;
  M << c.Theta1 + c.Theta2 + 2.0 * coupling, c.Theta2 + coupling, c.Theta2 + coupling, T(c.Theta2);
  return M;
}

// h(q, q'): gravity and velocity terms of M q'' = h + (M_R, M_alpha).
template <class T>
Vector2<T> bias_forces(const Model& model, const State<T>& x) {
  using std::sin;
  const InertiaConstants c = inertia_constants(model);
  const T& phi = x[0];
  const T& alpha = x[1];
  const T& phi_rate = x[2];
  const T& alpha_rate = x[3];
  const T sa = sin(alpha), sin_psi = sin(phi + alpha);
  return Vector2<T>(c.chi1 * sa * alpha_rate * (2.0 * phi_rate + alpha_rate) + model.g * (c.chi2 * sin(phi) + c.chi3 * sin_psi),
                    -c.chi1 * sa * phi_rate * phi_rate + model.g * c.chi3 * sin_psi);
}

// (m1 + m2) a_sp = A q'' + c (A.66 without gravity): the columns of A multiply phi'', alpha''.
template <class T>
struct CentreOfMassAcceleration {
  Matrix2<T> A;
  Vector2<T> c;
};

template <class T>
CentreOfMassAcceleration<T> centre_of_mass_acceleration(const Model& model, const State<T>& x) {
  using std::cos;
  using std::sin;
  const InertiaConstants k = inertia_constants(model);
  const T psi = x[0] + x[1];
  const T psi_rate = x[2] + x[3];
  const Vector2<T> e1_phi(cos(x[0]), -sin(x[0])), e1_psi(cos(psi), -sin(psi));
  const Vector2<T> r_phi(sin(x[0]), cos(x[0])), r_psi(sin(psi), cos(psi));
  CentreOfMassAcceleration<T> out;
  out.A.col(0) = k.chi2 * e1_phi + k.chi3 * e1_psi;
  out.A.col(1) = k.chi3 * e1_psi;
  out.c = -(k.chi2 * x[2] * x[2]) * r_phi - (k.chi3 * psi_rate * psi_rate) * r_psi;
  return out;
}

// Root of M_R = -s k |u + v M_R| with sign s of the sliding rate (k |v| < 1 always holds: k = r mu
// is 7e-3 m). Returns 0 for a frictionless model.
// Bilinear products without complex conjugation (Eigen's dot/squaredNorm conjugate, which would
// break complex-step derivatives).
template <class T>
T product(const Vector2<T>& a, const Vector2<T>& b) {
  return a[0] * b[0] + a[1] * b[1];
}

template <class T>
T solve_friction_moment(double k, double s, const Vector2<T>& u, const Vector2<T>& v) {
  using std::sqrt;
  if (k == 0.0) return T(0.0);
  const double k2 = k * k;
  const T uv = product(u, v);
  const T a = 1.0 - k2 * product(v, v);
  return (k2 * uv - s * sqrt(k2 * k2 * uv * uv + a * k2 * product(u, u))) / a;
}

template <class T>
struct Accelerations {
  Vector2<T> qdd;       // (phi'', alpha'')
  T friction_moment;    // M_R (eq. A.69), opposes phi'
};

// q'' for hip torque M_alpha, friction solved exactly (see the header comment).
template <class T>
Accelerations<T> accelerations(const Model& model, const State<T>& x, const T& hip_torque) {
  const Matrix2<T> M = mass_matrix(model, x[1]);
  const T det = M(0, 0) * M(1, 1) - M(0, 1) * M(1, 0);  // > 0 (A.60)
  Matrix2<T> Minv;
  Minv << M(1, 1) / det, -M(0, 1) / det, -M(1, 0) / det, M(0, 0) / det;  // (A.23)
  const Vector2<T> h = bias_forces(model, x) + Vector2<T>(T(0.0), hip_torque);
  Accelerations<T> out;
  const double k = model.bar_radius * model.friction_coefficient;
  if (k == 0.0) {
    out.friction_moment = T(0.0);
  } else {
    const CentreOfMassAcceleration<T> com = centre_of_mass_acceleration(model, x);
    const Vector2<T> weight(T(0.0), T(model.total_mass() * model.g));
    const Vector2<T> u = com.A * (Minv * h) + com.c + weight;
    const Vector2<T> v = com.A * Minv.col(0);
    out.friction_moment = solve_friction_moment(k, ad::value(x[2]) >= 0.0 ? 1.0 : -1.0, u, v);
  }
  out.qdd = Minv * (h + Vector2<T>(out.friction_moment, T(0.0)));
  return out;
}

// x' = (phi', alpha', phi'', alpha'').
template <class T>
State<T> state_derivative(const Model& model, const State<T>& x, const T& hip_torque) {
  const Accelerations<T> a = accelerations(model, x, hip_torque);
  return State<T>(x[2], x[3], a.qdd[0], a.qdd[1]);
}

// Hip torque that produces the accelerations q'' (eq. 3.9, second row of M q'' = h + ...).
template <class T>
T hip_torque_for(const Model& model, const State<T>& x, const Vector2<T>& qdd) {
  const Matrix2<T> M = mass_matrix(model, x[1]);
  return M(1, 0) * qdd[0] + M(1, 1) * qdd[1] - bias_forces(model, x)[1];
}

// Bar reaction |F| = (m1 + m2) |a_sp + g e_y| (A.67) for given accelerations.
template <class T>
T bar_normal_force(const Model& model, const State<T>& x, const Vector2<T>& qdd) {
  const CentreOfMassAcceleration<T> com = centre_of_mass_acceleration(model, x);
  const Vector2<T> F = com.A * qdd + com.c + Vector2<T>(T(0.0), T(model.total_mass() * model.g));
  using std::sqrt;
  return sqrt(product(F, F));
}

}  // namespace cyclopt::giant_swing
