#pragma once
// The reference for kkt_sensitivity.hpp: d f*/d p by a central difference of re-solved optima,
// (f*(p (1 + h)) - f*(p (1 - h))) / (2 h p), each solve warm-started from the optimum at p (its x
// and, for Ipopt, its multipliers). Costs two solves per parameter; for tests and benchmarks.

#include "cyclopt/nlp/solver_options.hpp"
#include "cyclopt/walker/gait_problem.hpp"

#include <string>

namespace cyclopt::studies {

struct ResolvedSensitivity {
  std::string name;
  double value = 0.0;
  double derivative = 0.0;  // central difference of the re-solved optima; valid only if converged
  double objective_decrease = 0.0, objective_increase = 0.0;  // f* at p (1 - h), p (1 + h)
  bool converged = false;   // both solves converged (not merely "acceptable")
  int iterations = 0;       // of both solves
  double seconds = 0.0;     // of both solves
  std::string message;      // the failing solve's termination, empty if converged
};

// model, problem, z and at: the problem as solved and its optimum. relative_step h in (0, 1);
// the parameter must be nonzero, neither free nor derived (throws std::invalid_argument).
ResolvedSensitivity resolved_sensitivity(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                                         const Eigen::VectorXd& z, const nlp::SolverSummary& at, const std::string& parameter,
                                         double relative_step, const nlp::SolverOptions& solver);

}  // namespace cyclopt::studies
