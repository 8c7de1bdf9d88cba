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

}  // namespace cyclopt::python
