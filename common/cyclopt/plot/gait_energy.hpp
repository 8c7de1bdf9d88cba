#pragma once
// The energies of a stored step (seed 001 section 9.1, Fig. 9.5) at sample k of its trajectory,
// from the stored q_s = [theta; q_b] and dq_s/dt with the walker's own mass matrix and heights
// (walker/stance_dynamics.hpp), in J.

#include "cyclopt/records/gait_records.hpp"
#include "cyclopt/walker/walker_model.hpp"

#include <cstddef>

namespace cyclopt::plot {

double kinetic_energy_at(const walker::WalkerModel<double>& m, const records::GaitTrajectoryRecord& tr, std::size_t k);
// E_tot = E_pot + E_kin.
double total_energy_at(const walker::WalkerModel<double>& m, const records::GaitTrajectoryRecord& tr, std::size_t k);

}  // namespace cyclopt::plot
