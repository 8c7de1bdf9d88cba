#pragma once
// The common fields of a spec (service/common_job_fields.hpp) as the kinds' solvers take them:
// the "solver" block applied on top of a kind's default options, and back in the spec's form.

#include "cyclopt/nlp/solver_options.hpp"
#include "cyclopt/service/common_job_fields.hpp"

#include <nlohmann/json.hpp>

namespace cyclopt::jobs {

// `base` with what the spec's "solver" block sets.
nlp::SolverOptions solver_options(const service::SolverOverrides& overrides, const nlp::SolverOptions& base);

// The "solver" block that sets every field of SolverOverrides to `options`' (for a resolved spec,
// service/resolved_spec.hpp): applied to any base, it gives `options` in those fields.
nlohmann::json solver_json(const nlp::SolverOptions& options);

}  // namespace cyclopt::jobs
