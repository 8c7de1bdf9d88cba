#pragma once
// A starting gait described by a few physical quantities instead of 30 Bezier coefficients, and
// its translation into the independent gait parameters x = alpha_tilde of seed 001 eq. (5.92).
//
// The seed found its first periodic gait by trial (section 8.1). Here the impact posture is built
// from a contact distance, knee flexions, a torso lean and two foot roll angles (both feet on the
// ground, eq. 5.47/5.55 solved for the leg angles). alpha_{M-1} sets the joint rates just before
// the impact (eq. 5.54b): the stance leg keeps rotating with the phase variable, the swing leg has
// come to rest and the stance foot pushes off. alpha_1 then follows from the impact (eq. 5.62), and
// alpha_2..alpha_{M-2} interpolate linearly between alpha_1 and alpha_{M-1}, plus a swing-knee
// flexion bump for ground clearance. Angles follow segment_parameters.hpp: a leg segment
// pointing straight down has absolute angle pi; foot roll angles are profile angles
// theta_F - theta_F,0 (0: sole flat, < 0: on the heel, > 0: rolled towards the toes).

#include "cyclopt/walker/walker_model.hpp"

#include <Eigen/Core>

namespace cyclopt::walker {

struct GaitShape {
  double contact_distance = 0.6;    // horizontal distance C1 -> C2 at impact (m)
  double torso_lean = 0.05;         // forward torso angle theta_T at impact (rad)
  double stance_knee = 0.05;        // theta_K1 at impact (rad)
  double swing_knee = 0.10;         // theta_K2 at impact (rad)
  double swing_knee_bump = 0.5;     // added to the swing knee's interior Bezier coefficients (rad)
  double push_off_rate = 1.5;       // d theta_F1 / d theta just before the impact, feet only
  double push_off_roll = 0.35;      // stance foot profile angle at impact (rad), feet only
  double heel_strike_roll = -0.20;  // swing foot profile angle at impact (rad), feet only
};

// x = [alpha_2; ...; alpha_{M-1}; alpha_tilde_M] for the shape. Throws std::invalid_argument (naming
// the field) when no posture with both feet on the ground has that contact distance.
Eigen::VectorXd gait_parameters(const WalkerModel<double>& model, const GaitShape& shape);

}  // namespace cyclopt::walker
