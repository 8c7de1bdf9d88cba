#pragma once
// Drawing-side kinematics of the biped (seed 001 section 5.1.3, Fig. 5.1): where the joints, the
// torso tip, the feet and the rolling contact point are at one configuration q_s = [theta; q_b] of
// the single-support phase. Positions come from the walker's own stance_frame() and
// point_position(); this file only adds the drawn extras (torso tip, foot outlines).

#include "cyclopt/records/gait_records.hpp"
#include "cyclopt/walker/stance_kinematics.hpp"

#include <array>
#include <vector>

namespace cyclopt::plot {

using Xz = std::array<double, 2>;  // (x, z) in metres, stance ankle at x_0 = 0 (eq. 5.4)

struct WalkerPose {
  Xz torso_tip, hip, knee1, knee2, ankle1, ankle2;  // 1: stance leg, 2: swing leg
  std::vector<Xz> foot1, foot2;  // closed outlines (empty for point feet)
  Xz contact;                    // rolling contact point C1 = A1 + [F''_A; -F'_A] on the ground z = 0
  Xz contact_in_foot;            // C1 in the stance foot's frame (the outline's), ankle at 0 (0 for point feet)
  Xz swing_lowest;               // lowest point of the swing foot C2 (eq. 5.5)
};

// `foot_outline`: outline points in the foot frame (plot::foot_outline); at a foot angle theta_F
// it is turned by -(theta_F - theta_F,0) about the ankle (the angle convention of e(phi)).
WalkerPose walker_pose(const walker::WalkerModel<double>& m, const walker::CoordinateVector<double>& q,
                       const std::vector<Xz>& foot_outline);

// q_s at time t of a stored step by linear interpolation of its time grid (t clamped to the step).
walker::CoordinateVector<double> q_at(const records::GaitTrajectoryRecord& trajectory, double t);

}  // namespace cyclopt::plot
