#pragma once
// What a stored job records to be reproduced (issue 17 item 7): its spec with every default
// filled in, and the random seeds it uses.
//
//   resolved spec  {"scene", "task", "name", "limits" (as requested, before the server's caps)}
//                  and the kind's own fields from JobKind::resolve, complete for every kind: the
//                  walker kinds (walker_job_json.hpp: foot as full parameters, speeds, start x,
//                  solver, multistart, continuation), foot_sweep (foot, sweep values, samples),
//                  foot_comparison (reference and feet as full parameters with their names),
//                  foot_design (start foot, free parameters, bounds, densities, sweep fields),
//                  foot_fit (trials, toe_bound), giant_swing (giant_swing_job_spec.hpp: every
//                  option of the method, solver). Validated and resolved again, it is itself.
//   seeds          every field named "seed" or "seeds" in the resolved spec, by path: {"multistart.seed": 1},
//                  {"multistart.seeds": [1, 2, 3]}
//                  (a kind keeps its random seeds in fields of that name).

#include "cyclopt/service/job_spec.hpp"

#include <nlohmann/json.hpp>

namespace cyclopt::service {

nlohmann::json resolved_spec(const ValidatedJobSpec& v);

nlohmann::json random_seeds(const nlohmann::json& resolved);

}  // namespace cyclopt::service
