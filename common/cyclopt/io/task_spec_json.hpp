#pragma once
// A giant-swing task (giant_swing/task_spec.hpp: the four tasks of seed 000, chapter 5) as users
// write it, with strict validation, and back.
//
// JSON (angles in degrees as in the seed's tables, torques in Nm), e.g.
//   {"task": "single_swing", "omega_deg_s": 40, "weights": {"jerk": 0.01},
//    "alpha_ddot_max_deg_s2": 10000,
//    "optimiser": {"support_points": 4, "max_support_points": 16, "initial_step": 20}}
// Every field but "task" is optional (defaults: giant_swing/task_spec.hpp); unknown keys and
// out-of-range values are SpecErrors naming the field (as a JSON path such as
// "task.weights.jerk") and its admissible range.


#include "cyclopt/errors/spec_error.hpp"
#include "cyclopt/giant_swing/task_spec.hpp"

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace cyclopt::io {

// Parses and validates; `path` prefixes field names in SpecError messages.
giant_swing::TaskSpec task_spec_from_json(const nlohmann::json& j, const std::string& path = "task");
nlohmann::json to_json(const giant_swing::TaskSpec& spec);

}  // namespace cyclopt::io
