#pragma once
// One-point evaluation cache in front of a Problem, counting evaluations into a SolverSummary.
// Both solvers ask for values and derivatives at the same x several times (Ipopt: eval_f, eval_g,
// eval_grad_f, eval_jac_g; SQP: line-search point, then its derivatives): the problem is
// evaluated once per x, and values-only results are upgraded when derivatives are asked for.
// Non-finite results count as evaluation failures (the seed's "no real solution", eq. 5.87).
// With SolverOptions::should_stop, every evaluation first asks it; once it says stop, evaluate()
// fails without evaluating and stopped() is true, so a solver ends (user_stop) within one
// evaluation however long its iterations are (large P, difference Hessians, line searches).

#include "cyclopt/nlp/problem.hpp"
#include "cyclopt/nlp/solver_options.hpp"

#include <Eigen/Core>

#include <functional>

namespace cyclopt::nlp {

class CachedEvaluator {
 public:
  // `counts` receives function_/jacobian_/failed_evaluations; both must outlive the evaluator.
  CachedEvaluator(Problem& problem, SolverSummary& counts, std::function<bool()> should_stop = {});

  // Evaluates at x unless the cached point is x (and has derivatives if requested).
  // Throws std::logic_error if the problem returns wrongly sized results.
  const EvaluationStatus& evaluate(const Eigen::VectorXd& x, bool with_derivatives);
  const Evaluation& evaluation() const { return evaluation_; }  // of the last evaluate()
  bool stopped() const { return stopped_; }  // should_stop refused an evaluation
  Problem& problem() const { return problem_; }
  // Adds the evaluations a helper evaluator made on a copy of the problem (parallel_columns.hpp).
  void add_counts(const SolverSummary& helper);

 private:
  void check_sizes(bool with_derivatives) const;

  Problem& problem_;
  SolverSummary& counts_;
  std::function<bool()> should_stop_;
  bool stopped_ = false;
  Eigen::VectorXd x_;
  bool valid_ = false;
  bool has_derivatives_ = false;
  EvaluationStatus status_;
  Evaluation evaluation_;
};

}  // namespace cyclopt::nlp
