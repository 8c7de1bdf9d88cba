#pragma once
// Charts of optimal gaits over walking speed, one curve per job (foot, objective): cost of
// transport (seed 001 Fig. 9.19a), maximal joint torques (Fig. 9.4), step length (Fig. 9.6a) and
// Floquet multiplier (Fig. 9.6b). Only converged points are drawn; a legend entry says how many
// points of a curve were left out.

#include "cyclopt/plot/line_chart.hpp"
#include "cyclopt/plot/walker_job_results.hpp"

#include <vector>

namespace cyclopt::plot {

LineChart cost_of_transport_chart(const std::vector<WalkerJobResults>& jobs);
// Colour per joint; the curves of the second and later jobs are dashed.
LineChart max_torque_chart(const std::vector<WalkerJobResults>& jobs);
LineChart step_length_chart(const std::vector<WalkerJobResults>& jobs);
LineChart floquet_chart(const std::vector<WalkerJobResults>& jobs);

}  // namespace cyclopt::plot
