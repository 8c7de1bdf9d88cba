#pragma once
// `cyclopt query JOB` for people: one line per stored walker point with the quantities users look
// for first (seed 001 ch. 9): speed, f_mech (or the objective), step length, period, cadence,
// Floquet multiplier, impact loss, status and curve; a foot_fit point its model, RMS and max
// residual and fitted parameters (records/foot_fit_record.hpp); a foot_design density its design
// (records/foot_design_records.hpp); a foot_comparison's foot its mean f_mech, saving and speeds
// (records/foot_comparison_records.hpp). Rows of other kinds (foot sweeps, giant
// swings) and --wide show every scalar column instead (row_table.hpp). The gait is read through
// the result contract (records/gait_records.hpp).

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace cyclopt::client {

// The summary of one solutions row (result_queries.hpp), columns in display order; nullopt when
// the row is not a walker gait (no values.gait, or one that is not a records::GaitRecord).
std::optional<nlohmann::ordered_json> point_summary(const nlohmann::json& solution_row);

// A foot_comparison's headline, from its reference's summary among `solution_rows`: what the
// best foot at each speed saves against the reference; nullopt for other jobs.
std::optional<std::string> comparison_envelope_line(const nlohmann::json& solution_rows);

}  // namespace cyclopt::client
