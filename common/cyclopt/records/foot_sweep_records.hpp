#pragma once
// The foot sweep family of the result contract (jobs/foot/foot_sweep_kind.cpp; seed 001 ch. 3,
// appendix E): per grid value of one foot parameter, the foot's mass properties and admissible
// angles as the point's values, its rolling kinematics sampled over those angles as the point's
// trajectory. SI units (m, rad, kg, kg m^2).

#include "cyclopt/records/json_fields.hpp"
#include "cyclopt/records/point_record.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace cyclopt::records {

struct FootMassRecord {
  double area = kUnset, mass = kUnset;
  double com_x = kUnset, com_z = kUnset, com_distance = kUnset;  // centre of mass from the ankle
  double inertia_ankle = kUnset, inertia_com = kUnset;
  double theta_F0 = kUnset;                   // eq. (E.7)
  double theta_min = kUnset, theta_max = kUnset;  // the admissible rolling angles
  bool operator==(const FootMassRecord&) const = default;
};

// One sample of the rolling kinematics at foot angle theta.
struct RollingSampleRecord {
  double theta = kUnset, ankle_x = kUnset, ankle_z = kUnset;
  double contact_x_from_ankle = kUnset, contact_z_from_ankle = kUnset, curvature_radius = kUnset;
  bool operator==(const RollingSampleRecord&) const = default;
};

struct FootRollingRecord {
  std::vector<RollingSampleRecord> samples;  // ascending in theta
  bool operator==(const FootRollingRecord&) const = default;
};

void to_json(nlohmann::json& j, const FootMassRecord& m);
void from_json(const nlohmann::json& j, FootMassRecord& m);  // throws RecordError naming the field
void to_json(nlohmann::json& j, const RollingSampleRecord& s);
void from_json(const nlohmann::json& j, RollingSampleRecord& s);
// An array of samples.
void to_json(nlohmann::json& j, const FootRollingRecord& r);
void from_json(const nlohmann::json& j, FootRollingRecord& r);

template <>
inline constexpr bool is_point_values<FootMassRecord> = true;
template <>
inline constexpr bool is_point_trajectory<FootRollingRecord> = true;

}  // namespace cyclopt::records
