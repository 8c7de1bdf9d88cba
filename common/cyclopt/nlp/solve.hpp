#pragma once
// The one entry point for solving an NLP: dispatches on SolverOptions::solver.

#include "cyclopt/nlp/problem.hpp"
#include "cyclopt/nlp/solver_options.hpp"

#include <Eigen/Core>

#include <limits>

namespace cyclopt::nlp {

// Throws std::invalid_argument for invalid options (naming the field) or a wrongly sized x0.
SolverSummary solve(Problem& problem, const SolverOptions& options, const Eigen::VectorXd& x0);

// solve(), then, while the result is not accepted (and not stopped), up to `restarts` fresh solves
// from the last final point: a fresh solve starts with a fresh Hessian approximation, which takes
// solves that stalled near an optimum (MaxFun, no merit decrease, with kkt_only a step below
// TolStep) the rest of the way. A solve that ends with a constraint violation above
// max_violation is not solved again: it stopped far from any KKT point, where a fresh Hessian does
// not help. Nor is a solve that ended at its own start (bitwise): a solve is a function of its
// start, so the restart would repeat it (the rho 10 foot design's start 11 spent 9 s on such a
// second restart, bench/results/foot_design_bench.txt). The summary is the last solve's, with the
// iterations, evaluations and seconds of all of them and the earlier stops named in its message.
// Throws as solve(), and std::invalid_argument for restarts < 0 or max_violation < 0 or NaN.
SolverSummary solve_with_restarts(Problem& problem, const SolverOptions& options, const Eigen::VectorXd& x0, int restarts,
                                  Acceptance acceptance = Acceptance::kkt_or_acceptable,
                                  double max_violation = std::numeric_limits<double>::infinity());

}  // namespace cyclopt::nlp
