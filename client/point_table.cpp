#include "point_table.hpp"

namespace cyclopt::client {
namespace {

nlohmann::json member(const nlohmann::json& object, const char* key) {
  return object.is_object() && object.contains(key) ? object[key] : nlohmann::json();
}

}  // namespace

std::optional<nlohmann::ordered_json> point_summary(const nlohmann::json& row) {
  const nlohmann::json values = member(row, "values");
  const nlohmann::json gait = member(values, "gait");
  if (!gait.is_object()) return std::nullopt;
  nlohmann::ordered_json s;
  s["curve"] = member(row, "curve");
  s["point"] = member(row, "point");
  s["speed_m_s"] = member(row, "parameter");
  const nlohmann::json f_mech = member(gait, "f_mech");
  s["f_mech"] = f_mech;  // eq. 5.102
  const nlohmann::json objective = member(gait, "objective");
  if (objective != f_mech) s["objective"] = objective;  // f_usq jobs (eq. 5.101)
  s["step_length_m"] = member(gait, "step_length");
  const nlohmann::json period = member(gait, "step_period");
  s["period_s"] = period;
  // steps per minute: one step per period
  s["cadence_1_min"] = period.is_number() && period.get<double>() > 0 ? nlohmann::json(60.0 / period.get<double>())
                                                                      : nlohmann::json();
  s["floquet"] = member(gait, "floquet_multiplier");  // eq. 5.89, stable for |Lambda| < 1
  s["impact_loss_J"] = member(gait, "impact_energy_loss");
  s["status"] = member(row, "status");
  return s;
}

}  // namespace cyclopt::client
