#pragma once
// Energy and total angular momentum about the bar (seed 000, eq. 3.4-3.7 = A.62-A.64).
// dE/dt = M_R phi' + M_alpha alpha' (friction and hip power) and dL/dt = M_R + M_G: the tests
// check both along integrated trajectories.

#include "cyclopt/giant_swing/equations_of_motion.hpp"

namespace cyclopt::giant_swing {

template <class T>
T kinetic_energy(const Model& model, const State<T>& x) {
  using std::cos;
  const InertiaConstants c = inertia_constants(model);
  const T psi_rate = x[2] + x[3];
  return 0.5 * c.Theta1 * x[2] * x[2] + 0.5 * c.Theta2 * psi_rate * psi_rate + c.chi1 * cos(x[1]) * x[2] * psi_rate;
}

// Zero at the bar height.
template <class T>
T potential_energy(const Model& model, const State<T>& x) {
  using std::cos;
  const InertiaConstants c = inertia_constants(model);
  return model.g * (c.chi2 * cos(x[0]) + c.chi3 * cos(x[0] + x[1]));
}

template <class T>
T total_energy(const Model& model, const State<T>& x) {
  return kinetic_energy(model, x) + potential_energy(model, x);
}

// L_ges (eq. 3.4).
template <class T>
T angular_momentum(const Model& model, const State<T>& x) {
  using std::cos;
  const InertiaConstants c = inertia_constants(model);
  return c.Theta1 * x[2] + c.chi1 * cos(x[1]) * (2.0 * x[2] + x[3]) + c.Theta2 * (x[2] + x[3]);
}

// Gravity moment M_G (eq. 3.6); dL/dt = M_R + M_G (eq. 3.5, 3.7).
template <class T>
T gravity_moment(const Model& model, const State<T>& x) {
  using std::sin;
  const InertiaConstants c = inertia_constants(model);
  return model.g * (c.chi2 * sin(x[0]) + c.chi3 * sin(x[0] + x[1]));
}

}  // namespace cyclopt::giant_swing
