#include "cyclopt/giant_swing/evaluation.hpp"

#include <cmath>

namespace cyclopt::giant_swing {

double failed_swing_score(double phi_in_round) { return 1000.0 * (1.0 + (kTwoPi - phi_in_round)); }

double completed_swing_score(const EvaluationWeights& w, const RoundResult& r, double omega) {
  return w.phi_rate * std::abs(r.phi_rate / omega - 1.0) +
         kDegPerRad * (w.alpha * std::abs(r.alpha) + w.alpha_rate * std::abs(r.alpha_rate)) +
         w.friction * r.friction_loss + w.jerk * r.jerk + w.moment * r.torque_integral;
}

double evaluation_score(const EvaluationWeights& w, const SimulationResult& s, int rounds_requested, double omega) {
  const int completed = int(s.rounds.size());
  const double phi_in_round = s.failure_phi - kTwoPi * completed;
  if (rounds_requested == 1) return s.failed ? failed_swing_score(phi_in_round) : completed_swing_score(w, s.rounds[0], omega);
  if (completed == 0) return failed_swing_score(phi_in_round) * 1e20;
  double sum = 0.0;
  for (const RoundResult& r : s.rounds) sum += completed_swing_score(w, r, omega);
  return sum * std::pow(10.0, 20 - 3 * completed);
}

}  // namespace cyclopt::giant_swing
