#include "cyclopt/records/walker_point_record.hpp"

#include "cyclopt/records/json_fields.hpp"

#include <cmath>

namespace cyclopt::records {

bool solved(const WalkerPointRecord& p) { return p.gait && p.gait->real && (!p.solver || p.solver->success); }

void to_json(nlohmann::json& j, const ContinuationStepRecord& c) {
  j = {{"curve_id", c.curve_id},
       {"on_grid", c.on_grid},
       {"converged", c.converged},
       {"predictor_attempts", c.predictor_attempts},
       {"predictor_steps", c.predictor_steps},
       {"trust_region", c.trust_region},
       {"point_seconds", c.point_seconds}};
  if (std::isfinite(c.kappa)) j["kappa"] = c.kappa;
}

void from_json(const nlohmann::json& j, ContinuationStepRecord& c) {
  const std::string r = "values";
  c.curve_id = integer(j, r, "curve_id");
  c.on_grid = boolean(j, r, "on_grid");
  c.converged = boolean(j, r, "converged");
  c.predictor_attempts = integer(j, r, "predictor_attempts");
  c.predictor_steps = integer(j, r, "predictor_steps");
  c.kappa = optional_number(j, r, "kappa").value_or(kUnset);
  c.trust_region = number(j, r, "trust_region");
  c.point_seconds = number(j, r, "point_seconds");
}

void to_json(nlohmann::json& j, const WalkerPointRecord& p) {
  j = nlohmann::json::object();
  if (p.gait) j["gait"] = *p.gait;
  if (p.solver) j["solver"] = *p.solver;
  if (p.start) j["start"] = *p.start;
  if (p.start_objective) j["start_objective"] = *p.start_objective;
  if (p.continuation) j.update(nlohmann::json(*p.continuation));
  if (!p.x.empty()) j["x"] = p.x;
  if (p.sensitivities) j["sensitivities"] = *p.sensitivities;
}

void from_json(const nlohmann::json& j, WalkerPointRecord& p) {
  const std::string r = "values";
  p = WalkerPointRecord{};
  if (!j.is_object()) throw RecordError(r + ": must be an object, got " + std::string(j.type_name()));
  if (j.contains("gait")) p.gait = j["gait"].get<GaitRecord>();
  if (j.contains("solver")) p.solver = j["solver"].get<SolverRecord>();
  p.start = optional_text(j, r, "start");
  p.start_objective = optional_number(j, r, "start_objective");
  if (j.contains("curve_id")) p.continuation = j.get<ContinuationStepRecord>();
  if (j.contains("x")) p.x = numbers(j, r, "x");
  if (j.contains("sensitivities")) p.sensitivities = j["sensitivities"].get<KktSensitivitiesRecord>();
}

}  // namespace cyclopt::records
