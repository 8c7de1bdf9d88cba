#pragma once
// The gait records of the result contract (records/gait_records.hpp) as Python objects, under one
// table of names with units: the scalars as "f_mech [-]", "step_length [m]", ... (the columns of
// Job.points() and the scalars of evaluate_gait), the trajectories as NumPy arrays, one row per
// coordinate (or joint, or x/z) and one column per grid sample (Job.trajectory, evaluate_gait).

#include "cyclopt/records/gait_records.hpp"

#include <pybind11/pybind11.h>

#include <span>

namespace cyclopt::python {

struct GaitScalarColumn {
  const char* name;  // with its unit
  double records::GaitRecord::*member;
};

// Every double of GaitRecord (seed 001 ch. 5), in the record's order.
std::span<const GaitScalarColumn> gait_scalar_columns();

// {"real": bool, "failure": str, "stable": bool, name [unit]: float, ..., "bezier_coefficients": array}
pybind11::dict gait_scalars(const records::GaitRecord& gait);

// {"time [s]": (P,), "theta [rad]": (P,), "q [rad]": (n+1, P), ...}; "stance_foot_angle [rad]" only
// for feet.
pybind11::dict gait_trajectories(const records::GaitTrajectoryRecord& trajectory);

// The same from any trajectory whose members are named as the record's (the evaluator's own,
// walker::GaitTrajectory, skips the record's copies): `array` turns a member into a NumPy array,
// one row per coordinate.
template <class Trajectory, class Arrays>
pybind11::dict trajectory_arrays(const Trajectory& t, const Arrays& array) {
  pybind11::dict d;
  d["time [s]"] = array(t.time);
  d["theta [rad]"] = array(t.theta);
  d["q [rad]"] = array(t.q);  // q_s = [theta; q_b]
  d["q_dot [rad/s]"] = array(t.q_dot);
  d["torque [N m]"] = array(t.torque);                // eq. 5.35
  d["contact_force [N]"] = array(t.contact_force);    // [F_1x; F_1z], eq. 5.14
  d["hip [m]"] = array(t.hip);                        // [x_H; z_H] from the stance ankle
  d["swing_contact [m]"] = array(t.swing_contact);    // [x_C2; z_C2]
  if (t.stance_foot_angle.size() != 0) d["stance_foot_angle [rad]"] = array(t.stance_foot_angle);
  return d;
}

}  // namespace cyclopt::python
