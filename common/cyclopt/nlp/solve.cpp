#include "cyclopt/nlp/solve.hpp"

#include "cyclopt/nlp/ipopt_solver.hpp"
#include "cyclopt/nlp/sqp_solver.hpp"

#include <stdexcept>

namespace cyclopt::nlp {

SolverSummary solve(Problem& problem, const SolverOptions& options, const Eigen::VectorXd& x0) {
  switch (options.solver) {
    case SolverKind::ipopt: return solve_with_ipopt(problem, options, x0);
    case SolverKind::sqp: return solve_with_sqp(problem, options, x0);
  }
  throw std::invalid_argument("SolverOptions.solver: must be ipopt or sqp");
}

}  // namespace cyclopt::nlp
