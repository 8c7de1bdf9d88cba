#pragma once
// The one entry point for solving an NLP: dispatches on SolverOptions::solver.

#include "cyclopt/nlp/problem.hpp"
#include "cyclopt/nlp/solver_options.hpp"

#include <Eigen/Core>

namespace cyclopt::nlp {

// Throws std::invalid_argument for invalid options (naming the field) or a wrongly sized x0.
SolverSummary solve(Problem& problem, const SolverOptions& options, const Eigen::VectorXd& x0);

}  // namespace cyclopt::nlp
