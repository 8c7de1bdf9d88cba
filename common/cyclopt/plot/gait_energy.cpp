#include "cyclopt/plot/gait_energy.hpp"

#include "cyclopt/walker/stance_dynamics.hpp"

namespace cyclopt::plot {
namespace {

// Sample k of the stored rows (q or dq/dt) as a coordinate vector.
walker::CoordinateVector<double> sample(const std::vector<std::vector<double>>& rows, std::size_t k) {
  walker::CoordinateVector<double> out(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) out(static_cast<Eigen::Index>(r)) = rows[r].at(k);
  return out;
}

}  // namespace

double kinetic_energy_at(const walker::WalkerModel<double>& m, const records::GaitTrajectoryRecord& tr, std::size_t k) {
  return walker::kinetic_energy(m, walker::stance_frame(m, sample(tr.q, k)), sample(tr.q_dot, k));
}

double total_energy_at(const walker::WalkerModel<double>& m, const records::GaitTrajectoryRecord& tr, std::size_t k) {
  const walker::StanceFrame<double> f = walker::stance_frame(m, sample(tr.q, k));  // one frame for both energies
  return walker::kinetic_energy(m, f, sample(tr.q_dot, k)) + walker::potential_energy(m, f);
}

}  // namespace cyclopt::plot
