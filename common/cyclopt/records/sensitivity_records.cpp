#include "cyclopt/records/sensitivity_records.hpp"

#include <cmath>

namespace cyclopt::records {

bool is_sensitivity_summary(const nlohmann::json& values) {
  return values.is_object() && values.contains("verdict") && values.contains("predicted_increase");
}

bool is_sensitivity_step(const nlohmann::json& values) {
  return values.is_object() && values.contains("relative_change") && values.contains("delta_objective");
}

void to_json(nlohmann::json& j, const ActiveSetChangeRecord& c) {
  j = {{"relative_change", finite_or_null(c.relative_change)}, {"constraint", c.constraint}, {"enters", c.enters}};
}

void from_json(const nlohmann::json& j, ActiveSetChangeRecord& c) {
  const std::string r = "active set change";
  c = ActiveSetChangeRecord{};
  const double x = number(j, r, "relative_change");
  c.relative_change = std::isnan(x) ? std::numeric_limits<double>::infinity() : x;  // null: none predicted
  c.constraint = text(j, r, "constraint");
  c.enters = boolean(j, r, "enters");
}

void to_json(nlohmann::json& j, const ParameterSensitivityRecord& p) {
  j = {{"name", p.name},
       {"value", finite_or_null(p.value)},
       {"derivative", finite_or_null(p.derivative)},
       {"relative", finite_or_null(p.relative)},
       {"kink", p.kink},
       {"decrease", p.decrease},
       {"increase", p.increase},
       {"weakly_active", p.weakly_active}};
}

void from_json(const nlohmann::json& j, ParameterSensitivityRecord& p) {
  const std::string r = "sensitivity";
  p = ParameterSensitivityRecord{};
  p.name = text(j, r, "name");
  p.value = number(j, r, "value");
  p.derivative = number(j, r, "derivative");
  p.relative = number(j, r, "relative");
  p.kink = boolean(j, r, "kink");
  p.decrease = member(j, r, "decrease").get<ActiveSetChangeRecord>();
  p.increase = member(j, r, "increase").get<ActiveSetChangeRecord>();
  p.weakly_active = texts(j, r, "weakly_active");
}

void to_json(nlohmann::json& j, const KktSensitivitiesRecord& k) {
  j = {{"multipliers", k.multipliers},
       {"objective", finite_or_null(k.objective)},
       {"lagrangian_gradient", finite_or_null(k.lagrangian_gradient)},
       {"active_constraints", k.active_constraints},
       {"unique_multipliers", k.unique_multipliers},
       {"weakly_active", k.weakly_active},
       {"parameters", k.parameters},
       {"seconds", finite_or_null(k.seconds)}};
  if (k.unavailable) j["unavailable"] = *k.unavailable;
}

void from_json(const nlohmann::json& j, KktSensitivitiesRecord& k) {
  const std::string r = "sensitivities";
  k = KktSensitivitiesRecord{};
  if (!j.is_object()) throw RecordError(r + ": must be an object, got " + std::string(j.type_name()));
  k.unavailable = optional_text(j, r, "unavailable");
  k.multipliers = text(j, r, "multipliers");
  k.objective = number(j, r, "objective");
  k.lagrangian_gradient = number(j, r, "lagrangian_gradient");
  k.active_constraints = integer(j, r, "active_constraints");
  k.unique_multipliers = boolean(j, r, "unique_multipliers");
  k.weakly_active = texts(j, r, "weakly_active");
  const nlohmann::json& parameters = member(j, r, "parameters");
  if (!parameters.is_array()) throw RecordError(r + ".parameters: must be an array, got " + parameters.dump());
  for (const nlohmann::json& p : parameters) k.parameters.push_back(p.get<ParameterSensitivityRecord>());
  k.seconds = number(j, r, "seconds");
}

void to_json(nlohmann::json& j, const SensitivityStepRecord& s) {
  j = {{"parameter_name", s.parameter},
       {"value", finite_or_null(s.value)},
       {"relative_change", finite_or_null(s.relative_change)},
       {"delta_objective", finite_or_null(s.delta_objective)},
       {"curve_id", s.curve_id}};
}

void from_json(const nlohmann::json& j, SensitivityStepRecord& s) {
  const std::string r = "values";
  s = SensitivityStepRecord{};
  s.parameter = text(j, r, "parameter_name");
  s.value = number(j, r, "value");
  s.relative_change = number(j, r, "relative_change");
  s.delta_objective = number(j, r, "delta_objective");
  s.curve_id = integer(j, r, "curve_id");
}

void to_json(nlohmann::json& j, const SensitivitySummaryRecord& s) {
  j = {{"parameter_name", s.parameter},
       {"value", finite_or_null(s.value)},
       {"derivative", finite_or_null(s.derivative)},
       {"relative", finite_or_null(s.relative)},
       {"kink", s.kink},
       {"relative_range", finite_or_null(s.relative_range)},
       {"predicted_decrease", finite_or_null(s.predicted_decrease)},
       {"predicted_increase", finite_or_null(s.predicted_increase)},
       {"continuation_decrease", finite_or_null(s.continuation_decrease)},
       {"continuation_increase", finite_or_null(s.continuation_increase)},
       {"reached_decrease", finite_or_null(s.reached_decrease)},
       {"reached_increase", finite_or_null(s.reached_increase)},
       {"quotient_decrease", finite_or_null(s.quotient_decrease)},
       {"quotient_increase", finite_or_null(s.quotient_increase)},
       {"jumps", s.jumps},
       {"verdict", s.verdict}};
}

void from_json(const nlohmann::json& j, SensitivitySummaryRecord& s) {
  const std::string r = "values";
  s = SensitivitySummaryRecord{};
  s.parameter = text(j, r, "parameter_name");
  s.value = number(j, r, "value");
  s.derivative = number(j, r, "derivative");
  s.relative = number(j, r, "relative");
  s.kink = boolean(j, r, "kink");
  s.relative_range = number(j, r, "relative_range");
  s.predicted_decrease = number(j, r, "predicted_decrease");
  s.predicted_increase = number(j, r, "predicted_increase");
  s.continuation_decrease = number(j, r, "continuation_decrease");
  s.continuation_increase = number(j, r, "continuation_increase");
  s.reached_decrease = number(j, r, "reached_decrease");
  s.reached_increase = number(j, r, "reached_increase");
  s.quotient_decrease = number(j, r, "quotient_decrease");
  s.quotient_increase = number(j, r, "quotient_increase");
  s.jumps = integer(j, r, "jumps");
  s.verdict = text(j, r, "verdict");
}

}  // namespace cyclopt::records
