#pragma once
// A walker gait and the summary of its solve as JSON, as the command line, the service and the
// plots store and read them.

#include "cyclopt/nlp/solver_options.hpp"
#include "cyclopt/walker/periodic_gait.hpp"

#include <nlohmann/json_fwd.hpp>

namespace cyclopt::io {

// Scalars of a gait (objective, f_mech, f_usq, step length and period, speed, Lambda, impact
// loss, largest inequality, stability) and, if `trajectories`, its states and torques on the grid.
nlohmann::json gait_to_json(const walker::PeriodicGait<double>& gait, bool trajectories);
// The summary of a solve, for reports.
nlohmann::json summary_to_json(const nlp::SolverSummary& summary);

}  // namespace cyclopt::io
