#pragma once
// The smoothing homotopy for f_mech (issue 52's yardstick for the kinked SQP): f_mech's positive
// part max(p, 0) of (5.100) replaced by the smooth (p + sqrt(p^2 + e^2)) / 2 (positive_power.hpp),
// solved for e = first, first * factor, ... down to last, each stage warm-started from the one
// before; then, with polish, a solve of the exact f_mech from the last stage's point. Early stages
// see a smooth, well-scaled problem far from any kink; later ones move the iterate towards the
// kinks the exact optimum sits on.

#include "cyclopt/nlp/solver_options.hpp"
#include "cyclopt/walker/gait_problem.hpp"

#include <optional>
#include <vector>

namespace cyclopt::walker {

struct SmoothingHomotopyOptions {
  // W, the first stage's e, in (0, kMaxPositivePowerSmoothing]: of the joint powers' size at low
  // speed. A wider e dominates f_mech (e/2 per joint and second) and drives the gait to the edge of
  // its real solutions (5.87): at 0.3 m/s, e = 10 W gave zeta_min / zeta+ ~ 2e-3.
  double first = 1.0;
  double last = 1e-2;   // W, the last stage's e, in (0, first]
  double factor = 0.1;  // e of a stage over the one before, in (0, 1)
  bool polish = true;   // a last solve of the exact f_mech
};

struct SmoothingHomotopySummary {
  std::vector<double> smoothing;             // W, e of each stage
  std::vector<nlp::SolverSummary> stages;    // one per stage, their objective the smoothed f_mech
  std::optional<nlp::SolverSummary> polish;  // with polish: the exact f_mech's solve
  const nlp::SolverSummary& final() const { return polish ? *polish : stages.back(); }
};

// `options` must pose f_mech with the seed's rule (no band, no smoothing); each stage and the
// polish solve with `solver`. A stage that ends without a point (at its start, or failing there)
// hands its start on. Throws std::invalid_argument for options out of range (naming the field).
SmoothingHomotopySummary solve_by_smoothing(const WalkerModel<double>& model, const GaitProblemOptions& options,
                                            const nlp::SolverOptions& solver, const Eigen::VectorXd& z0,
                                            const SmoothingHomotopyOptions& homotopy = {});

}  // namespace cyclopt::walker
