#pragma once
// The solver family of the result contract: the summary of the solve that produced a point
// (stored as values.solver), as nlp::SolverSummary reports it - its one encoding, also in the
// checkpoints a resumed sweep replays solves from (jobs/walker/sweep_checkpoints.hpp), which keep
// the multipliers too.

#include "cyclopt/records/json_fields.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace cyclopt::records {

struct SolverRecord {
  std::string termination;  // nlp::to_string(Termination): converged, acceptable, max_iterations, ...
  bool success = false;     // converged or acceptable
  std::string message;
  int iterations = 0, function_evaluations = 0, jacobian_evaluations = 0, failed_evaluations = 0;
  double wall_seconds = kUnset, objective = kUnset, kkt_error = kUnset, constraint_violation = kUnset;
  std::vector<double> x;  // the final iterate
  // Its multipliers (nlp::SolverSummary's sign convention); empty in a stored point's values, kept
  // in checkpoints so that a replayed solve warm-starts what follows as the original did.
  std::vector<double> equality_multipliers, inequality_multipliers, bound_multipliers;
  bool operator==(const SolverRecord&) const = default;
};

void to_json(nlohmann::json& j, const SolverRecord& s);
void from_json(const nlohmann::json& j, SolverRecord& s);  // throws RecordError naming the field

}  // namespace cyclopt::records
