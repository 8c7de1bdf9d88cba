#pragma once
// Ipopt 3.11 adapter: solves any nlp::Problem with Ipopt's interior-point method.
//
// - exact first derivatives from Problem::evaluate; the Jacobian is passed with a dense sparsity
//   pattern; no second derivatives needed: the Hessian of the Lagrangian is the adapter's dense
//   damped BFGS passed through eval_h (default), forward differences of the exact gradients at every
//   iteration (small problems), or Ipopt's limited-memory approximation (IpoptOptions::hessian);
// - IpoptOptions::warm_start: x0 with multipliers, warm_start_init_point=yes, small mu_init;
// - an evaluation failure (EvaluationStatus !ok, or a non-finite value) is returned as `false`
//   from eval_*, so Ipopt cuts back the step (the seed's "no real solution", eq. 5.87);
// - app->Initialize("") always: no stray ipopt.opt is read;
// - SolverOptions::on_iteration is called from intermediate_callback; max_wall_seconds is
//   enforced there too (Ipopt 3.11's own limit counts CPU seconds);
// - multipliers follow the convention of SolverSummary (Ipopt's own: same signs for the
//   constraints, bound_multipliers = z_U - z_L);
// - thread safety: Debian's Ipopt uses sequential MUMPS, which has global state, so Ipopt solves
//   are serialised by a process-wide lock (multistart with Ipopt gains no parallel speed-up).

#include "cyclopt/nlp/problem.hpp"
#include "cyclopt/nlp/solver_options.hpp"

#include <Eigen/Core>

namespace cyclopt::nlp {

SolverSummary solve_with_ipopt(Problem& problem, const SolverOptions& options, const Eigen::VectorXd& x0);

}  // namespace cyclopt::nlp
