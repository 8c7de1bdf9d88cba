#pragma once
// The gait family of the result contract: a walker gait's scalars (stored as a point's
// values.gait) and its trajectories on the phase grid (stored as the point's "json" trajectory
// blob). Seed 001 ch. 5: f_mech eq. (5.102), f_usq eq. (5.101), Floquet multiplier eq. (5.89),
// stable per eq. (5.90), the virtual constraints' Bezier coefficients eq. (5.16).

#include "cyclopt/records/json_fields.hpp"
#include "cyclopt/records/point_record.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace cyclopt::records {

struct GaitRecord {
  bool real = false;
  std::string failure;  // why there is no real periodic gait (real == false; the numbers are then NaN)
  double objective = kUnset;  // the job's objective (f_mech or f_usq)
  double f_mech = kUnset, f_usq = kUnset;
  double mean_speed = kUnset;   // m/s
  double step_length = kUnset;  // m
  double step_period = kUnset;  // s
  double floquet_multiplier = kUnset;
  bool stable = false;
  double impact_energy_loss = kUnset;  // J
  double max_inequality = kUnset, speed_equality = kUnset;
  double theta_plus = kUnset, theta_minus = kUnset;  // rad
  std::vector<std::vector<double>> bezier_coefficients;  // one row per actuated joint
  bool operator==(const GaitRecord&) const = default;
};

// One row per coordinate (or joint, or x/z), one column per grid sample.
struct GaitTrajectoryRecord {
  std::vector<double> time, theta;  // s, rad
  std::vector<std::vector<double>> q, q_dot, torque, contact_force, hip, swing_contact;
  std::vector<double> stance_foot_angle;  // empty for point feet
  bool operator==(const GaitTrajectoryRecord&) const = default;
};

// Not-real gaits store only real and failure. from_json throws RecordError naming the field.
void to_json(nlohmann::json& j, const GaitRecord& g);
void from_json(const nlohmann::json& j, GaitRecord& g);
void to_json(nlohmann::json& j, const GaitTrajectoryRecord& t);
void from_json(const nlohmann::json& j, GaitTrajectoryRecord& t);

template <>
inline constexpr bool is_point_trajectory<GaitTrajectoryRecord> = true;

}  // namespace cyclopt::records
