#pragma once
// The fields every job spec shares (job_spec.hpp), parsed and validated once into plain values.
// A job kind gets them next to its own fields (JobKind::parse) and never reads them from JSON:
//
//   name       at most 200 characters
//   objective  f_mech (cost of transport of the positive mechanical work, seed 001 eq. 5.102) |
//              f_usq (squared torques, eq. 5.101)
//   solver     {solver: ipopt | sqp, max_iterations 1..100000, optimality_tolerance /
//              constraint_tolerance in [1e-14, 1], print_level 0..12}: overrides of the kind's
//              default solver options
//   limits     {max_wall_seconds in (0, 604800], max_iterations 1..1e9}, each capped by the server's
// They stay plain values here, as the spec names them; the kinds turn them into their solver's
// options and their scene's objective (jobs/solver_fields.hpp).

#include "cyclopt/service/job_context.hpp"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

namespace cyclopt::service {

// The spec's "solver" block: what it sets, on top of a kind's defaults.
struct SolverOverrides {
  std::optional<std::string> solver;  // "ipopt" | "sqp"
  std::optional<int> max_iterations;
  std::optional<double> optimality_tolerance;
  std::optional<double> constraint_tolerance;
  std::optional<int> print_level;
};

// The spec's "limits": what the submitter asked for, before the server's caps.
struct RequestedLimits {
  std::optional<double> max_wall_seconds;
  std::optional<int> max_iterations;
};

struct CommonJobFields {
  std::string name;                            // "" when not given
  std::optional<std::string> objective;        // "f_mech" | "f_usq"; nullopt: the kind's default
  SolverOverrides solver;
  RequestedLimits limits;
};

// The keys of a spec that every kind accepts (scene, task and the fields above).
const std::vector<std::string>& common_job_field_names();

// Throws SpecError naming the first invalid field and its admissible range.
CommonJobFields parse_common_job_fields(const nlohmann::json& spec);

// The requested limits, each capped by the server's.
JobLimits effective_limits(const RequestedLimits& requested, const JobLimits& server_caps);

}  // namespace cyclopt::service
