#include "cyclopt/walker/smoothing_homotopy.hpp"

#include "cyclopt/nlp/solve.hpp"

#include <stdexcept>
#include <string>

namespace cyclopt::walker {

SmoothingHomotopySummary solve_by_smoothing(const WalkerModel<double>& model, const GaitProblemOptions& options,
                                            const nlp::SolverOptions& solver, const Eigen::VectorXd& z0,
                                            const SmoothingHomotopyOptions& h) {
  if (!(h.first > 0.0 && h.first <= kMaxPositivePowerSmoothing))
    throw std::invalid_argument("first: must be in (0, " + std::to_string(kMaxPositivePowerSmoothing) + "] W");
  if (!(h.last > 0.0 && h.last <= h.first)) throw std::invalid_argument("last: must be in (0, first] W");
  if (!(h.factor > 0.0 && h.factor < 1.0)) throw std::invalid_argument("factor: must be in (0, 1)");
  if (options.objective != Objective::mechanical || options.positive_power_band > 0.0 || options.positive_power_smoothing > 0.0)
    throw std::invalid_argument("options: the homotopy solves f_mech with the seed's rule (no band, no smoothing)");
  SmoothingHomotopySummary out;
  Eigen::VectorXd z = z0;
  // e_k = first * factor^k while e_k >= last (with a relative margin: 10 * 0.1^3 is 0.00999...).
  for (double e = h.first; e >= h.last * (1.0 - 1e-9); e *= h.factor) {
    GaitProblemOptions smoothed = options;
    smoothed.positive_power_smoothing = e;
    GaitProblem problem(model, smoothed);
    out.smoothing.push_back(e);
    out.stages.push_back(nlp::solve(problem, solver, z));
    const nlp::SolverSummary& s = out.stages.back();
    if (s.x.size() == z.size() && s.x.allFinite()) z = s.x;
  }
  if (h.polish) {
    GaitProblem exact(model, options);
    out.polish = nlp::solve(exact, solver, z);
  }
  return out;
}

}  // namespace cyclopt::walker
