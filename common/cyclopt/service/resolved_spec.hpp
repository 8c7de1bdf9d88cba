#pragma once
// What a stored job records to be reproduced (issue 17 item 7): its spec with every default
// filled in, and the random seeds it uses.
//
//   resolved spec  {"scene", "task", "name", "limits" (as requested, before the server's caps)}
//                  and the kind's own fields from JobKind::resolve, which the walker kinds fill
//                  completely (walker_job_json.hpp): foot as full parameters, speeds, start x,
//                  solver, multistart, continuation. A kind without resolve adds its fields as
//                  submitted and "resolved": false.
//   seeds          every field named "seed" in the resolved spec, by path: {"multistart.seed": 1}
//                  (a kind keeps its random seeds in fields of that name).

#include "cyclopt/service/job_spec.hpp"

#include <nlohmann/json.hpp>

namespace cyclopt::service {

// `submitted`: the spec as submitted (validated into `v`).
nlohmann::json resolved_spec(const ValidatedJobSpec& v, const nlohmann::json& submitted);

nlohmann::json random_seeds(const nlohmann::json& resolved);

}  // namespace cyclopt::service
