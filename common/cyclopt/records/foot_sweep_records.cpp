#include "cyclopt/records/foot_sweep_records.hpp"

namespace cyclopt::records {

void to_json(nlohmann::json& j, const FootMassRecord& m) {
  j = {{"area", m.area},
       {"mass", m.mass},
       {"com_x", m.com_x},
       {"com_z", m.com_z},
       {"com_distance", m.com_distance},
       {"inertia_ankle", m.inertia_ankle},
       {"inertia_com", m.inertia_com},
       {"theta_F0", m.theta_F0},
       {"theta_min", m.theta_min},
       {"theta_max", m.theta_max}};
}

void from_json(const nlohmann::json& j, FootMassRecord& m) {
  const std::string r = "values";
  m = {number(j, r, "area"),          number(j, r, "mass"),        number(j, r, "com_x"),
       number(j, r, "com_z"),         number(j, r, "com_distance"), number(j, r, "inertia_ankle"),
       number(j, r, "inertia_com"),   number(j, r, "theta_F0"),    number(j, r, "theta_min"),
       number(j, r, "theta_max")};
}

void to_json(nlohmann::json& j, const RollingSampleRecord& s) {
  j = {{"theta", s.theta},
       {"ankle_x", s.ankle_x},
       {"ankle_z", s.ankle_z},
       {"contact_x_from_ankle", s.contact_x_from_ankle},
       {"contact_z_from_ankle", s.contact_z_from_ankle},
       {"curvature_radius", s.curvature_radius}};
}

void from_json(const nlohmann::json& j, RollingSampleRecord& s) {
  const std::string r = "trajectory";
  s = {number(j, r, "theta"),
       number(j, r, "ankle_x"),
       number(j, r, "ankle_z"),
       number(j, r, "contact_x_from_ankle"),
       number(j, r, "contact_z_from_ankle"),
       number(j, r, "curvature_radius")};
}

void to_json(nlohmann::json& j, const FootRollingRecord& r) { j = r.samples; }

void from_json(const nlohmann::json& j, FootRollingRecord& r) {
  if (!j.is_array()) throw RecordError("trajectory: must be an array of rolling samples, got " + std::string(j.type_name()));
  r.samples = j.get<std::vector<RollingSampleRecord>>();
}

}  // namespace cyclopt::records
