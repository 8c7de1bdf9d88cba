#pragma once
// Kinematics of a foot rolling without slip on flat ground, expressed through F (seed 001).

#include "cyclopt/foot/foot_profile.hpp"

#include <Eigen/Core>

namespace cyclopt::foot {

template <class T>
using Vector2 = Eigen::Matrix<T, 2, 1>;

// Ankle position [x_A; z_A] while the foot rolls, eq. (5.10a) / (3.9)-(3.10a); x_0 is the
// integration constant of eq. (2.20).
template <class T>
Vector2<T> ankle_position(const RollingContact<T>& c, const T& x0 = T(0.0)) {
  return Vector2<T>(c.F + x0, c.dF);
}

// Ankle velocity d/dt [x_A; z_A] = r'(theta) theta_dot, eq. (5.10b).
template <class T>
Vector2<T> ankle_velocity(const RollingContact<T>& c, const T& theta_dot) {
  return Vector2<T>(c.dF * theta_dot, c.ddF * theta_dot);
}

// Potential contact point relative to the ankle, r_AC = F'' e_x - F' e_z, eq. (5.5) / (3.10b).
template <class T>
Vector2<T> contact_point_from_ankle(const RollingContact<T>& c) {
  return Vector2<T>(c.ddF, -c.dF);
}

// Horizontal position of the contact point on the ground, x_C = x_0 + F + F'', eq. (2.21).
// Its derivative with respect to theta is the curvature radius (eq. 2.32).
template <class T>
T contact_point_on_ground(const RollingContact<T>& c, const T& x0 = T(0.0)) {
  return x0 + c.F + c.ddF;
}

}  // namespace cyclopt::foot
