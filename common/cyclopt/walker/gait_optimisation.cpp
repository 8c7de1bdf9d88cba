#include "cyclopt/walker/gait_optimisation.hpp"

#include "cyclopt/nlp/solve.hpp"

namespace cyclopt::walker {

GaitOptimum optimise_gait(const WalkerModel<double>& model, const GaitProblemOptions& options,
                          const nlp::SolverOptions& solver, const std::optional<Eigen::VectorXd>& start) {
  GaitProblem problem(model, options);
  GaitOptimum out;
  const GaitStart start_point = gait_start(GaitEvaluator(model), options.speed, start);
  out.start = start_point.origin;
  const Eigen::VectorXd z0 = problem.initial_point(start_point.x);
  nlp::Evaluation e0;
  if (problem.evaluate(z0, false, e0).ok) out.start_objective = e0.objective;
  out.summary = nlp::solve(problem, solver, z0);
  // A feasible f_mech run that did not pass the KKT test usually sits at the kink of (5.100) where
  // the gait holds a joint still (positive_power.hpp): say what lets the test settle.
  const bool feasible_unsettled = !out.summary.success() && out.summary.termination != nlp::Termination::user_stop &&
                                  out.summary.constraint_violation <= 1e-6;
  if (feasible_unsettled && options.objective == Objective::mechanical && options.positive_power_band == 0.0 &&
      options.positive_power_smoothing == 0.0)
    out.summary.message += kUnsettledKinkHint;
  out.z = out.summary.x.size() == z0.size() ? out.summary.x : z0;
  out.model = problem.model_at(out.z);
  out.gait = problem.gait_at(out.z);
  return out;
}

}  // namespace cyclopt::walker
