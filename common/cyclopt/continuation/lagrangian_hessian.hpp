#pragma once
// The Hessian of the Lagrangian (seed 001, eq. 6.23) by forward differences of the exact (AD)
// Lagrangian gradient, for the QP predictor's W = clamped Hessian (6.24) of Algorithm 2 steps 3
// and 7. The seed uses the complex step; the walker's gradients are exact dual-number
// derivatives, so one difference per variable costs n + 1 Jacobian evaluations (on two threads
// when a core is spare, nlp/parallel_columns.hpp).
#include "cyclopt/nlp/problem.hpp"
#include <Eigen/Core>
#include <optional>

namespace cyclopt::continuation {

// Multipliers y_eq, y_in (sign convention of nlp::SolverSummary) held fixed; `at` is the
// evaluation with derivatives at x. A difference step that leaves the bounds or fails to evaluate
// is taken backwards; a variable where both fail gets a zero column. Returns the symmetric part.
Eigen::MatrixXd lagrangian_hessian(nlp::Problem& problem, const Eigen::VectorXd& x, const nlp::Evaluation& at,
                                   const Eigen::VectorXd& equality_multipliers,
                                   const Eigen::VectorXd& inequality_multipliers);

}  // namespace cyclopt::continuation
