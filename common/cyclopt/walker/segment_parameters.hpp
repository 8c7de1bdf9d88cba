#pragma once
// Mass and length parameters of the planar biped, p_mech of seed 001 (Fig. 5.1b, Table 5.1), and
// the constants of the optimisation problem (Table 5.1 lower part).
//
// Conventions (derived from eq. 5.55 and Table D.1, see docs/walker_model.md): every segment
// direction is e(phi) = [sin phi; cos phi] in the (x, z) plane, angles measured from the upward
// vertical, positive towards walking direction +x. Centre-of-mass offsets r_* are measured from
// the proximal joint: torso and thighs from the hip, shanks from the knee, feet from the ankle.

#include <array>
#include <string_view>

namespace cyclopt::walker {

// p_mech in the order of seed 001 section 5.1: lengths, CoM offsets, masses, inertias.
enum SegmentIndex {
  l_T = 0, l_O, l_U, r_T, r_O, r_U, r_F, m_T, m_O, m_U, m_F, J_T, J_O, J_U, J_F, segment_parameter_count
};

template <class T>
using SegmentParameters = std::array<T, segment_parameter_count>;

// Names in JSON and reports ("l_T", "r_O", ...), units and admissible ranges.
struct SegmentParameterInfo {
  std::string_view name;
  std::string_view unit;
  double min;
  double max;
};
const SegmentParameterInfo& segment_parameter_info(int index);

// Table 5.1: 80 kg, 1.80 m adult (foot models HM / HMT).
SegmentParameters<double> table_5_1();
// Table D.1: point feet; foot mass and inertia merged into the shank (r_F = m_F = J_F = 0).
SegmentParameters<double> table_d_1();

// Constants of the walking problem (Table 5.1, lower part).
struct WalkingConstants {
  double gravity = 9.81;          // g (m/s^2)
  double friction = 0.6;          // mu_H, static friction coefficient
  double actuator_constant = 1.0; // c_A (W/(N m)^2), eq. (5.99)
  int bezier_degree = 6;          // M
  int points = 200;               // P, discretisation of the phase variable (eq. 5.93)
};

inline constexpr double kFootZeroAngle = 2.246;  // theta_F,0 of Table 5.1 (rad)

}  // namespace cyclopt::walker
