#include "cyclopt/records/gait_records.hpp"

#include "cyclopt/records/json_fields.hpp"

namespace cyclopt::records {

void to_json(nlohmann::json& j, const GaitRecord& g) {
  j = {{"real", g.real}};
  if (!g.real) {
    j["failure"] = g.failure;
    return;
  }
  j["objective"] = g.objective;
  j["f_mech"] = g.f_mech;
  j["f_usq"] = g.f_usq;
  j["mean_speed"] = g.mean_speed;
  j["step_length"] = g.step_length;
  j["step_period"] = g.step_period;
  j["floquet_multiplier"] = g.floquet_multiplier;
  j["stable"] = g.stable;
  j["impact_energy_loss"] = g.impact_energy_loss;
  j["max_inequality"] = g.max_inequality;
  j["speed_equality"] = g.speed_equality;
  j["theta_plus"] = g.theta_plus;
  j["theta_minus"] = g.theta_minus;
  j["bezier_coefficients"] = g.bezier_coefficients;
}

void from_json(const nlohmann::json& j, GaitRecord& g) {
  const std::string r = "gait";
  g = GaitRecord{};
  g.real = boolean(j, r, "real");
  if (!g.real) {
    g.failure = text(j, r, "failure");
    return;
  }
  g.objective = number(j, r, "objective");
  g.f_mech = number(j, r, "f_mech");
  g.f_usq = number(j, r, "f_usq");
  g.mean_speed = number(j, r, "mean_speed");
  g.step_length = number(j, r, "step_length");
  g.step_period = number(j, r, "step_period");
  g.floquet_multiplier = number(j, r, "floquet_multiplier");
  g.stable = boolean(j, r, "stable");
  g.impact_energy_loss = number(j, r, "impact_energy_loss");
  g.max_inequality = number(j, r, "max_inequality");
  g.speed_equality = number(j, r, "speed_equality");
  g.theta_plus = number(j, r, "theta_plus");
  g.theta_minus = number(j, r, "theta_minus");
  g.bezier_coefficients = rows(j, r, "bezier_coefficients");
}

void to_json(nlohmann::json& j, const GaitTrajectoryRecord& t) {
  j = {{"time", t.time},   {"theta", t.theta},   {"q", t.q},
       {"q_dot", t.q_dot}, {"torque", t.torque}, {"contact_force", t.contact_force},
       {"hip", t.hip},     {"swing_contact", t.swing_contact}};
  if (!t.stance_foot_angle.empty()) j["stance_foot_angle"] = t.stance_foot_angle;
}

void from_json(const nlohmann::json& j, GaitTrajectoryRecord& t) {
  const std::string r = "trajectory";
  t = GaitTrajectoryRecord{};
  t.time = numbers(j, r, "time");
  t.theta = numbers(j, r, "theta");
  t.q = rows(j, r, "q");
  t.q_dot = rows(j, r, "q_dot");
  t.torque = rows(j, r, "torque");
  t.contact_force = rows(j, r, "contact_force");
  t.hip = rows(j, r, "hip");
  t.swing_contact = rows(j, r, "swing_contact");
  if (j.contains("stance_foot_angle")) t.stance_foot_angle = numbers(j, r, "stance_foot_angle");
}

}  // namespace cyclopt::records
