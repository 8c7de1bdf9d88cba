#pragma once
// A job specification (proto/schemas/job.schema.json), parsed and validated once into a
// ValidatedJobSpec: the fields every job shares (common_job_fields.hpp) and the typed spec of the
// job kind selected by "task" (JobKind::parse). The server keeps it from submission to run.
//
//   {"scene": "walker", "task": "foot_sweep", "name": "density study",
//    "foot": "P2-shoes-left-HMT", "sweep": {"parameter": "density", "values": "20:5:60"},
//    "limits": {"max_wall_seconds": 600, "max_iterations": 100000}}
//
// Common fields: scene (walker | giant_swing), task (evaluate | optimise | multistart |
// continuation | sweep | foot_sweep | foot_comparison | foot_design | foot_fit | giant_swing), and
// name, objective, solver, limits (common_job_fields.hpp).

#include "cyclopt/errors/spec_error.hpp"
#include "cyclopt/service/job_kind.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace cyclopt::service {

const std::vector<std::string>& known_scenes();
const std::vector<std::string>& known_tasks();  // every task of the job schema (job_schema.hpp), registered or not
const std::vector<std::string>& known_objectives();

struct ValidatedJobSpec {
  const JobKind* kind = nullptr;
  std::string scene;
  std::string task;
  CommonJobFields common;
  std::shared_ptr<const KindSpec> spec;  // kind->parse's result

  void run(JobContext& ctx) const { kind->run(*spec, ctx); }
  JobCost estimate() const { return kind->estimate ? kind->estimate(*spec) : JobCost{}; }
};

// Parses submitted text; throws SpecError("spec_json", ...) for malformed or non-object JSON.
nlohmann::json parse_job_spec_text(const std::string& text);

// Throws SpecError naming the first invalid field and its admissible values; a task of the
// schema that no registered kind implements is rejected as "not available on this server".
// Calls the kind's parse exactly once.
ValidatedJobSpec validate_job_spec(const nlohmann::json& spec, const JobKindRegistry& registry);

// parse_job_spec_text then validate_job_spec: a submission, or a spec stored as text.
ValidatedJobSpec validate_job_spec_text(const std::string& text, const JobKindRegistry& registry);

}  // namespace cyclopt::service
