#include "cyclopt/walker/held_joint_solve.hpp"

#include "cyclopt/nlp/solve.hpp"
#include "cyclopt/walker/held_joints.hpp"

#include <stdexcept>

namespace cyclopt::walker {

HeldJointSolve solve_on_held_joints(const WalkerModel<double>& model, const GaitProblemOptions& options,
                                    const nlp::SolverOptions& solver, const nlp::SolverSummary& start,
                                    const HeldJointSolveOptions& held) {
  if (!(held.still_ratio > 0.0 && held.still_ratio < 1.0)) throw std::invalid_argument("still_ratio: must be in (0, 1)");
  HeldJointSolve out;
  out.result = start;
  GaitProblem original(model, options);
  if (start.success() || solver.solver != nlp::SolverKind::sqp || !original.declares_kinks() || !options.free_parameters.empty() ||
      start.x.size() != original.num_variables() || !start.x.allFinite())
    return out;
  out.joints = held_joints(original.gait_at(start.x), held.still_ratio);
  if (out.joints.empty()) return out;
  HeldJointProblem manifold(model, options, out.joints);
  out.manifold = nlp::solve(manifold, solver, start.x);
  const nlp::SolverSummary& m = *out.manifold;
  nlp::Evaluation e;
  if (m.x.size() != start.x.size() || !m.x.allFinite() || !original.evaluate(m.x, false, e).ok) return out;
  // The original problem's tests at the manifold's point: one SQP iteration with the kinks modelled,
  // whose step 2 (the KKT test, then the nonsmooth one) ends the run as converged before any step.
  nlp::SolverOptions test = solver;
  test.sqp.kinks.enabled = true;
  test.max_iterations = 1;
  nlp::SolverSummary tested = nlp::solve(original, test, m.x);
  if (tested.termination == nlp::Termination::converged) {
    out.result = tested;
    return out;
  }
  const bool feasible = m.constraint_violation <= solver.constraint_tolerance;
  const bool start_feasible = start.constraint_violation <= solver.constraint_tolerance;
  if (feasible && (!start_feasible || e.objective < start.objective)) {
    out.result = m;  // not converged: the manifold run's own termination (stalled, max_iterations, ...)
    out.result.objective = e.objective;
    out.result.optimality = nlp::Optimality::none;
  }
  return out;
}

}  // namespace cyclopt::walker
