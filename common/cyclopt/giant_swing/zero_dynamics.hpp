#pragma once
// The reduced ("zero") dynamics of the gymnast on the virtual constraint alpha = b(phi), with phi as
// the independent variable (phi' > 0 throughout a giant swing, seed 000 ch. 3.2). With Y = phi'^2,
//   dY/dphi = 2 phi''(phi, Y)            (phi'' from constrained_accelerations, friction exact)
//   dt/dphi = 1 / phi'
//   d/dphi of 1/2 int alpha'''^2 dt = alpha'''^2 / (2 phi'),  alpha''' = phi' d(alpha'')/dphi along
//                                    the motion (a Tangent in the direction (1, dY/dphi))
//   d/dphi of int -M_R phi' dt = -M_R,   d/dphi of 1/2 int M_alpha^2 dt = M_alpha^2 / (2 phi').
// One swing is a fixed-step Cash-Karp integration over [0, 2 pi]: no event location, so ad::Dual
// coefficients give exact derivatives of the discrete map (the NLP of minimum_jerk_problem.hpp).

#include "cyclopt/autodiff/tangent.hpp"
#include "cyclopt/giant_swing/virtual_constraint.hpp"
#include "cyclopt/ode/cash_karp.hpp"

#include <vector>

namespace cyclopt::giant_swing {

// (Y = phi'^2, t, jerk integral, friction loss, torque integral) as functions of phi.
template <class T>
using ZeroDynamicsState = Eigen::Matrix<T, 5, 1>;

// The full state and accelerations at phase phi with phi'^2 = Y on alpha = b(phi).
template <class T>
ConstrainedAccelerations<T> accelerations_on_constraint(const Model& model, const BezierCoefficients<T>& c,
                                                        const T& phi, const T& Y) {
  using std::sqrt;
  const std::array<T, 4> b = bezier_hip_angle<T>(c, phi);
  const T phi_rate = sqrt(Y);
  const State<T> x(phi, b[0], phi_rate, b[1] * phi_rate);
  return constrained_accelerations(model, x, b[1], T(b[2] * Y));
}

template <class T>
ZeroDynamicsState<T> zero_dynamics_rate(const Model& model, const BezierCoefficients<T>& c, const T& phi,
                                        const ZeroDynamicsState<T>& z) {
  using std::sqrt;
  using Tg = ad::Tangent<T>;
  const T Y = z[0];
  const ConstrainedAccelerations<T> a = accelerations_on_constraint(model, c, phi, Y);
  const T Y_rate = 2.0 * a.phi_acceleration;
  const BezierCoefficients<Tg> ct = c.template cast<Tg>();
  const T alpha_acceleration_rate = accelerations_on_constraint(model, ct, Tg(phi, T(1.0)), Tg(Y, Y_rate)).alpha_acceleration.d;
  const T phi_rate = sqrt(Y);
  const T jerk = phi_rate * alpha_acceleration_rate;
  ZeroDynamicsState<T> rate;
  rate << Y_rate, 1.0 / phi_rate, 0.5 * jerk * jerk / phi_rate, -a.friction_moment,
      0.5 * a.hip_torque * a.hip_torque / phi_rate;
  return rate;
}

template <class T>
struct ReducedSwing {
  bool ok = false;               // phi' stayed positive
  ZeroDynamicsState<T> end;      // at phi = 2 pi
  std::vector<T> rate_squared;   // Y at the step nodes phi_k = 2 pi k / steps, k = 1..steps
};

// One swing from phi' = initial_rate on alpha = b(phi).
template <class T>
ReducedSwing<T> integrate_zero_dynamics(const Model& model, const BezierCoefficients<T>& c, double initial_rate,
                                        int steps) {
  using Z = ZeroDynamicsState<T>;
  ReducedSwing<T> out;
  Z z;
  z << T(initial_rate * initial_rate), T(0.0), T(0.0), T(0.0), T(0.0);
  auto rate = [&](const T& phi, const Z& y) { return zero_dynamics_rate(model, c, phi, y); };
  const double h = kTwoPi / steps;
  Z next = z, err = z;
  for (int k = 0; k < steps; ++k) {
    const T phi(h * k);
    // Y must stay positive inside the step too (the stages evaluate sqrt(Y)).
    if (!(ad::value(z[0]) > 0.0)) return out;
    ode::cash_karp_step(rate, phi, z, Z(rate(phi, z)), T(h), next, err);
    z = next;
    if (!(ad::value(z[0]) > 0.0) || !std::isfinite(ad::value(z[0]))) return out;
    out.rate_squared.push_back(z[0]);
  }
  out.ok = true;
  out.end = z;
  return out;
}

}  // namespace cyclopt::giant_swing
