#pragma once
// A job specification (proto/schemas/job.schema.json) and its validation. The fields every job
// shares are checked here; the job kind selected by "task" checks its own fields (JobKind).
//
//   {"scene": "walker", "task": "foot_sweep", "name": "density study",
//    "foot": "P2-shoes-left-HMT", "sweep": {"parameter": "density", "values": "20:5:60"},
//    "limits": {"max_wall_seconds": 600, "max_iterations": 100000}}
//
// Common fields: scene (walker | giant_swing), task (evaluate | optimise | multistart |
// continuation | sweep | foot_sweep | giant_swing), name (<= 200 chars), objective (f_mech: cost of transport of the positive mechanical work, seed 001 eq. 5.102 |
// f_usq: squared torques, eq. 5.101), solver {solver: ipopt | sqp, max_iterations 1..100000,
// optimality_tolerance / constraint_tolerance in [1e-14, 1], print_level 0..12}, limits
// {max_wall_seconds in (0, 604800], max_iterations 1..1e9}.

#include "cyclopt/service/job_kind.hpp"
#include "cyclopt/nlp/solver_options.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace cyclopt::service {

const std::vector<std::string>& known_scenes();
const std::vector<std::string>& known_tasks();  // every task of the schema, registered or not
const std::vector<std::string>& known_objectives();

struct ValidatedJobSpec {
  nlohmann::json spec;
  const JobKind* kind = nullptr;
  std::string scene;
  std::string task;
};

// Parses submitted text; throws SpecError("spec_json", ...) for malformed or non-object JSON.
nlohmann::json parse_job_spec_text(const std::string& text);

// Throws SpecError naming the first invalid field and its admissible values; a task of the
// schema that no registered kind implements is rejected as "not available on this server".
ValidatedJobSpec validate_job_spec(const nlohmann::json& spec, const JobKindRegistry& registry);

// The spec's "limits", each capped by the server's.
JobLimits effective_limits(const nlohmann::json& spec, const JobLimits& server_caps);

// The spec's "solver" block on top of `base` (default: SolverOptions defaults).
nlp::SolverOptions solver_options_from_spec(const nlohmann::json& spec, const nlp::SolverOptions& base = {});

}  // namespace cyclopt::service
