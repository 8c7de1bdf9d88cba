#pragma once
// One try of the QP predictor of seed 001, Algorithm 2 (steps 3-15): at the new parameter
// p_k + Delta p, two SQP steps d_1, d_2 from the current solution x_k, each with a full step
// (alpha = beta = 1) that must pass the merit test (6.19), with Hessians W_1, W_2 from (6.24),
// the BFGS retry (6.22) of d_2, and the convergence-rate estimate kappa (7.2). Whether the try
// is accepted (kappa < 1) and how the trust region reacts is the caller's (continuation_solver).
#include "cyclopt/nlp/problem.hpp"
#include "cyclopt/qp/active_set_solver.hpp"
#include <Eigen/Core>
#include <limits>

namespace cyclopt::continuation {

struct QpPredictorSettings {
  double eta = 1e-4;               // merit test (6.19)
  double active_tolerance = 1e-6;  // active inequalities for the multipliers (6.26) of W_1
  double constraint_tolerance = 1e-8;  // bounds within this are active for (6.26)
  double relative_min_penalty = 1e-3;  // sigma of (6.9)
  qp::ActiveSetOptions qp;             // for the subproblems (6.7)
  // Algorithm 2 computes W_2 from (6.24) at x_{k,1} (step 7) and falls back on the BFGS update
  // (6.22) of W_1 only if d_2 fails. false: W_2 is that BFGS update from the start, so a try
  // costs one difference Hessian (n Jacobians) instead of two (not in the seed).
  bool fresh_second_hessian = true;
};

enum class PredictorOutcome {
  no_step,     // step 18: d_1 failed (QP infeasible, no real solution, or merit test)
  first_step,  // step 17: only d_1 succeeded
  both_steps,  // steps 15-16: d_1 and d_2 succeeded; kappa is set
};

struct QpPredictorResult {
  PredictorOutcome outcome = PredictorOutcome::no_step;
  Eigen::VectorXd x;  // x_{k+1,0}: x_{k,2}, x_{k,1} or x_k by outcome
  Eigen::MatrixXd W;  // W_{k+1,0}: W_3, W_2 or W_1 by outcome (identity if x_k does not evaluate)
  Eigen::MatrixXd W1;  // the W_1 of this try (empty if x_k does not evaluate), for the next try at x_k
  double kappa = std::numeric_limits<double>::quiet_NaN();
  int steps = 0;        // QP solves (d_1, d_2, the BFGS retry of d_2)
};

// `problem` is the NLP at p_k + Delta p; x_k the solution at p_k. W1: W_1 of an earlier try from
// the same x_k (at another Delta p) to use instead of (6.24) at x_k and p_k + Delta p (not in the
// seed: the Hessian's change with Delta p is what the BFGS updates of the steps absorb).
QpPredictorResult qp_predictor(nlp::Problem& problem, const Eigen::VectorXd& x_k, const QpPredictorSettings& settings,
                               const Eigen::MatrixXd* W1 = nullptr);

}  // namespace cyclopt::continuation
