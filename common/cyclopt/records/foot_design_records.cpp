#include "cyclopt/records/foot_design_records.hpp"

namespace cyclopt::records {

namespace {

std::vector<int> integers(const nlohmann::json& j, const std::string& record, const std::string& key) {
  std::vector<int> out;
  for (double x : numbers(j, record, key)) out.push_back(static_cast<int>(x));
  return out;
}

}  // namespace

bool is_designed_foot(const nlohmann::json& values) {
  return values.is_object() && values.contains("optima") && values.contains("free_foot_speeds");
}

void to_json(nlohmann::json& j, const DesignedFoot& f) {
  nlohmann::json parameters = nlohmann::json::object();
  for (const auto& [name, value] : f.parameters) parameters[name] = finite_or_null(value);
  j = {{"parameters", parameters},
       {"m_F", finite_or_null(f.m_F)},
       {"r_F", finite_or_null(f.r_F)},
       {"J_F", finite_or_null(f.J_F)},
       {"theta_F0", finite_or_null(f.theta_F0)}};
}

void from_json(const nlohmann::json& j, DesignedFoot& f) {
  const std::string r = "design foot";
  f = DesignedFoot{};
  const nlohmann::json& parameters = member(j, r, "parameters");
  if (!parameters.is_object()) throw RecordError(r + ".parameters: must be an object, got " + parameters.dump());
  for (const auto& item : parameters.items()) f.parameters[item.key()] = number(parameters, r + ".parameters", item.key());
  f.m_F = number(j, r, "m_F");
  f.r_F = number(j, r, "r_F");
  f.J_F = number(j, r, "J_F");
  f.theta_F0 = number(j, r, "theta_F0");
}

void to_json(nlohmann::json& j, const DesignPointRecord& p) {
  j = {{"density", p.density},
       {"design_foot", p.foot},
       {"active_bounds", p.active_bounds},
       {"reached_by_starts", p.reached_by_starts},
       {"design", p.design}};
  if (p.design_class) j["design_class"] = *p.design_class;
  if (p.class_reason) j["class_reason"] = *p.class_reason;
}

void from_json(const nlohmann::json& j, DesignPointRecord& p) {
  const std::string r = "values";
  p = DesignPointRecord{};
  p.density = number(j, r, "density");
  p.foot = member(j, r, "design_foot").get<DesignedFoot>();
  p.active_bounds = texts(j, r, "active_bounds");
  p.reached_by_starts = integers(j, r, "reached_by_starts");
  p.design = boolean(j, r, "design");
  p.design_class = optional_text(j, r, "design_class");
  p.class_reason = optional_text(j, r, "class_reason");
}

void to_json(nlohmann::json& j, const DesignedFootRecord& d) {
  j = {{"density", d.density},
       {"admissible", d.admissible},
       {"starts", d.starts},
       {"kkt_starts", d.kkt_starts},
       {"optima", {{"admissible", d.admissible_optima},
                   {"stilt", d.stilt_optima},
                   {"wheel", d.wheel_optima},
                   {"no_rolling", d.no_rolling_optima},
                   {"under_resolved", d.under_resolved_optima}}},
       {"best", d.best},
       {"design_objective", finite_or_null(d.design_objective)},
       {"design", d.design},
       {"active_bounds", d.active_bounds},
       {"speeds", d.speeds},
       {"free_foot_speeds", d.free_foot_speeds},
       {"low_speed", finite_or_null(d.low_speed)},
       {"low_speed_design", d.low_speed_design},
       {"speeds_reached", d.speeds_reached},
       {"mean_f_mech", finite_or_null(d.mean_f_mech)},
       {"saving_vs_start", finite_or_null(d.saving_vs_start)},
       {"saving_vs_point", finite_or_null(d.saving_vs_point)},
       {"low_speeds_reached", d.low_speeds_reached},
       {"low_mean_f_mech", finite_or_null(d.low_mean_f_mech)},
       {"low_saving_vs_start", finite_or_null(d.low_saving_vs_start)},
       {"low_saving_vs_point", finite_or_null(d.low_saving_vs_point)},
       {"answer", d.answer},
       {"seconds", {{"multistart", finite_or_null(d.multistart_seconds)},
                    {"continuation", finite_or_null(d.continuation_seconds)},
                    {"sweeps", finite_or_null(d.sweep_seconds)},
                    {"total", finite_or_null(d.seconds)}}}};
  if (d.reason) j["reason"] = *d.reason;
  if (d.sensitivities) j["sensitivities"] = *d.sensitivities;
}

void from_json(const nlohmann::json& j, DesignedFootRecord& d) {
  const std::string r = "values";
  d = DesignedFootRecord{};
  d.density = number(j, r, "density");
  d.admissible = boolean(j, r, "admissible");
  d.reason = optional_text(j, r, "reason");
  d.starts = integer(j, r, "starts");
  d.kkt_starts = integer(j, r, "kkt_starts");
  const nlohmann::json& optima = member(j, r, "optima");
  d.admissible_optima = integer(optima, r + ".optima", "admissible");
  d.stilt_optima = integer(optima, r + ".optima", "stilt");
  d.wheel_optima = integer(optima, r + ".optima", "wheel");
  d.no_rolling_optima = integer(optima, r + ".optima", "no_rolling");
  d.under_resolved_optima = optima.contains("under_resolved") ? integer(optima, r + ".optima", "under_resolved") : 0;
  d.best = integer(j, r, "best");
  d.design_objective = number(j, r, "design_objective");
  d.design = member(j, r, "design").get<DesignedFoot>();
  d.active_bounds = texts(j, r, "active_bounds");
  d.speeds = integer(j, r, "speeds");
  d.free_foot_speeds = integer(j, r, "free_foot_speeds");
  d.low_speed = number(j, r, "low_speed");
  d.low_speed_design = member(j, r, "low_speed_design").get<DesignedFoot>();
  d.speeds_reached = integer(j, r, "speeds_reached");
  d.mean_f_mech = number(j, r, "mean_f_mech");
  d.saving_vs_start = number(j, r, "saving_vs_start");
  d.saving_vs_point = number(j, r, "saving_vs_point");
  d.low_speeds_reached = integer(j, r, "low_speeds_reached");
  d.low_mean_f_mech = number(j, r, "low_mean_f_mech");
  d.low_saving_vs_start = number(j, r, "low_saving_vs_start");
  d.low_saving_vs_point = number(j, r, "low_saving_vs_point");
  d.answer = optional_text(j, r, "answer").value_or("design");
  if (d.answer != "design" && d.answer != "low-speed design")
    throw RecordError(r + ".answer: must be \"design\" or \"low-speed design\", got \"" + d.answer + "\"");
  const nlohmann::json& seconds = member(j, r, "seconds");
  d.multistart_seconds = number(seconds, r + ".seconds", "multistart");
  d.continuation_seconds = number(seconds, r + ".seconds", "continuation");
  d.sweep_seconds = number(seconds, r + ".seconds", "sweeps");
  d.seconds = number(seconds, r + ".seconds", "total");
  if (j.contains("sensitivities")) d.sensitivities = j["sensitivities"].get<KktSensitivitiesRecord>();
}

}  // namespace cyclopt::records
