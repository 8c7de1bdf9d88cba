#pragma once
// Charts of optimal gaits over walking speed, one curve per job (foot, objective): cost of
// transport (seed 001 Fig. 9.19a), maximal joint torques (Fig. 9.4), step length (Fig. 9.6a) and
// Floquet multiplier (Fig. 9.6b), the relative impact loss (Fig. 9.5b), and the solution curves of one job (Fig. 9.1). Only converged points are drawn; a legend entry says how many
// points of a curve were left out.

#include "cyclopt/plot/line_chart.hpp"
#include "cyclopt/plot/walker_job_results.hpp"

#include <vector>

namespace cyclopt::plot {

LineChart cost_of_transport_chart(const std::vector<WalkerJobResults>& jobs);
// Colour per joint; the curves of the second and later jobs are dashed.
LineChart max_torque_chart(const std::vector<WalkerJobResults>& jobs);
LineChart step_length_chart(const std::vector<WalkerJobResults>& jobs);
// With the stability limits Λ = 1 (and Λ = -1 when a multiplier is negative) as reference lines:
// stable for |Λ| < 1 (eq. 5.90).
LineChart floquet_chart(const std::vector<WalkerJobResults>& jobs);
// The kinetic energy the impact ending each step dissipates relative to the kinetic energy after it,
// (E_kin^- - E_kin^+) / E_kin^+ in %, over speed (seed 001 Fig. 9.5b): the stored loss
// gait.impact_energy_loss over E_kin at the step's start, from its stored trajectory (gait_energy.hpp).
// Points without a trajectory are left out.
LineChart impact_loss_chart(const std::vector<WalkerJobResults>& jobs);
// Every solution curve the job stored (curves 1, 2, ... as `cyclopt query` numbers them) with the
// best point per speed (curve 0) as the envelope beneath them: the job's objective over speed
// (seed 001 Fig. 9.1). Throws std::invalid_argument when no curve has a converged point.
LineChart solution_curves_chart(const WalkerJobResults& job);

}  // namespace cyclopt::plot
