#pragma once
// One foot's finished speed sweep, reduced to its best point per speed (studies::FootSweepSummary),
// as a checkpoint value: the result a comparison's work unit leaves for its job
// (foot_comparison_kind.hpp), read back by the job to summarise the feet and by a resumed job
// instead of sweeping the foot again. JSON with every field, doubles in round-trip precision
// (sweep_checkpoints.hpp writes the curve points); mean, saving and common speeds are not kept,
// summarise_feet computes them from all feet.

#include "cyclopt/studies/foot_comparison.hpp"

#include <nlohmann/json.hpp>

namespace cyclopt::service {

nlohmann::json foot_sweep_to_json(const studies::FootSweepSummary& s);
// Throws (nlohmann::json::exception, std::out_of_range) on a malformed value.
studies::FootSweepSummary foot_sweep_from_json(const nlohmann::json& j);

}  // namespace cyclopt::service
