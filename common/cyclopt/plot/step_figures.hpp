#pragma once
// What happens within one step of a stored optimal gait (seed 001 Fig. 9.5 and section 9.1's
// reading of it), over the relative step time t/T from impact to impact:
//   joint-angles    the joint angles q_b (eq. 5.3) in degrees
//   joint-torques   the joint torques u (eq. 5.35)
//   joint-powers    the joint powers P_i = u_i dq_b,i/dt with their positive part shaded: what f_mech
//                   charges (eq. 5.100, 5.102); a joint held still under torque costs nothing
//   contact-point   the rolling contact point C1 along the stance sole, from the ankle, between the
//                   sole's heel and toe ends (feet only: a point foot has none)
//   energy          the increase of the total energy E_tot = E_pot + E_kin since the step's start
//                   (Fig. 9.5a) beside the work the joint torques did until then, the integral of
//                   sum_i P_i: the contact rolls without slipping, so the two agree (energy balance)
// read from the point's stored trajectory (records::GaitTrajectoryRecord).

#include "cyclopt/plot/walker_figures.hpp"

#include <vector>

namespace cyclopt::plot {

LineChart joint_angle_chart(const WalkerJobResults& job, const GaitPoint& point);
LineChart joint_torque_chart(const WalkerJobResults& job, const GaitPoint& point);
// One series per joint; its band runs from 0 up to max(P_i, 0), with the zero crossings between
// two samples located by linear interpolation (as f_mech's trapezoid rule does, Fig. 5.3).
LineChart joint_power_chart(const WalkerJobResults& job, const GaitPoint& point);
// Throws std::invalid_argument for point feet.
LineChart contact_point_chart(const WalkerJobResults& job, const GaitPoint& point);

// E_tot(t) - E_tot(0) from the stored q, dq/dt (stance_dynamics.hpp) and the trapezoid integral of
// the joint powers, both in J over t/T.
LineChart energy_chart(const WalkerJobResults& job, const GaitPoint& point);

// The five figures (the contact point only with feet); throws std::invalid_argument when the
// point has no stored trajectory.
std::vector<Figure> within_step_figures(const WalkerJobResults& job, const GaitPoint& point);

}  // namespace cyclopt::plot
