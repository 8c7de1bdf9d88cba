#include "cyclopt/nlp/solve.hpp"

#include "cyclopt/nlp/ipopt_solver.hpp"
#include "cyclopt/nlp/sqp_solver.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace cyclopt::nlp {

SolverSummary solve(Problem& problem, const SolverOptions& options, const Eigen::VectorXd& x0) {
  switch (options.solver) {
    case SolverKind::ipopt: return solve_with_ipopt(problem, options, x0);
    case SolverKind::sqp: return solve_with_sqp(problem, options, x0);
  }
  throw std::invalid_argument("SolverOptions.solver: must be ipopt or sqp");
}

SolverSummary solve_with_restarts(Problem& problem, const SolverOptions& options, const Eigen::VectorXd& x0, int restarts,
                                  Acceptance acceptance, double max_violation) {
  if (restarts < 0) throw std::invalid_argument("restarts: must be >= 0");
  if (!(max_violation >= 0.0)) throw std::invalid_argument("max_violation: must be >= 0");
  SolverSummary run = solve(problem, options, x0);
  Eigen::VectorXd start = x0;  // of the last solve
  for (int k = 1; k <= restarts && !accepted(run, acceptance) && run.termination != Termination::user_stop && run.x.size() > 0 &&
                  run.x.allFinite() && run.constraint_violation <= max_violation &&
                  (run.x.size() != start.size() || run.x != start);
       ++k) {
    start = run.x;
    SolverSummary again = solve(problem, options, start);
    again.iterations += run.iterations;
    again.function_evaluations += run.function_evaluations;
    again.jacobian_evaluations += run.jacobian_evaluations;
    again.failed_evaluations += run.failed_evaluations;
    again.qp_iterations += run.qp_iterations;
    again.wall_seconds += run.wall_seconds;
    again.message += " (restart " + std::to_string(k) + " after: " + run.message + ")";
    run = std::move(again);
  }
  return run;
}

}  // namespace cyclopt::nlp
