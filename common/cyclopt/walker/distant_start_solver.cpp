#include "cyclopt/walker/distant_start_solver.hpp"

namespace cyclopt::walker {

nlp::SolverOptions distant_start_solver(nlp::SolverOptions solver, int hessian_refresh) {
  solver.sqp.difference_hessian = true;
  solver.sqp.difference_hessian_every = hessian_refresh;
  solver.sqp.max_qp_iterations = kDistantStartQpIterations;
  if (solver.ipopt.hessian == nlp::IpoptHessian::damped_bfgs) {
    solver.ipopt.difference_hessian_start = true;
    solver.ipopt.difference_hessian_every = hessian_refresh;
  }
  return solver;
}

}  // namespace cyclopt::walker
