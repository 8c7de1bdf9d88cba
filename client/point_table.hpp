#pragma once
// `cyclopt query JOB` for people: one line per stored walker point with the quantities users look
// for first (seed 001 ch. 9): speed, f_mech (or the objective), step length, period, cadence,
// Floquet multiplier, impact loss, status and curve; a foot_fit point its model, RMS and max
// residual and fitted parameters (records/foot_fit_record.hpp); a foot_design density its design
// (records/foot_design_records.hpp). Rows of other kinds (foot sweeps, giant
// swings) and --wide show every scalar column instead (row_table.hpp). The gait is read through
// the result contract (records/gait_records.hpp).

#include <nlohmann/json.hpp>

#include <optional>

namespace cyclopt::client {

// The summary of one solutions row (result_queries.hpp), columns in display order; nullopt when
// the row is not a walker gait (no values.gait, or one that is not a records::GaitRecord).
std::optional<nlohmann::ordered_json> point_summary(const nlohmann::json& solution_row);

}  // namespace cyclopt::client
