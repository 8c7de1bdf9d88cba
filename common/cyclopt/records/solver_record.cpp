#include "cyclopt/records/solver_record.hpp"

#include "cyclopt/records/json_fields.hpp"

namespace cyclopt::records {

void to_json(nlohmann::json& j, const SolverRecord& s) {
  j = {{"termination", s.termination},
       {"success", s.success},
       {"message", s.message},
       {"iterations", s.iterations},
       {"function_evaluations", s.function_evaluations},
       {"jacobian_evaluations", s.jacobian_evaluations},
       {"failed_evaluations", s.failed_evaluations},
       {"wall_seconds", s.wall_seconds},
       {"objective", s.objective},
       {"kkt_error", s.kkt_error},
       {"constraint_violation", s.constraint_violation},
       {"x", s.x}};
  if (!s.equality_multipliers.empty()) j["equality_multipliers"] = s.equality_multipliers;
  if (!s.inequality_multipliers.empty()) j["inequality_multipliers"] = s.inequality_multipliers;
  if (!s.bound_multipliers.empty()) j["bound_multipliers"] = s.bound_multipliers;
}

void from_json(const nlohmann::json& j, SolverRecord& s) {
  const std::string r = "solver";
  s.termination = text(j, r, "termination");
  s.success = boolean(j, r, "success");
  s.message = text(j, r, "message");
  s.iterations = integer(j, r, "iterations");
  s.function_evaluations = integer(j, r, "function_evaluations");
  s.jacobian_evaluations = integer(j, r, "jacobian_evaluations");
  s.failed_evaluations = integer(j, r, "failed_evaluations");
  s.wall_seconds = number(j, r, "wall_seconds");
  s.objective = number(j, r, "objective");
  s.kkt_error = number(j, r, "kkt_error");
  s.constraint_violation = number(j, r, "constraint_violation");
  s.x = numbers(j, r, "x");
  s.equality_multipliers = j.contains("equality_multipliers") ? numbers(j, r, "equality_multipliers") : std::vector<double>{};
  s.inequality_multipliers = j.contains("inequality_multipliers") ? numbers(j, r, "inequality_multipliers") : std::vector<double>{};
  s.bound_multipliers = j.contains("bound_multipliers") ? numbers(j, r, "bound_multipliers") : std::vector<double>{};
}

}  // namespace cyclopt::records
