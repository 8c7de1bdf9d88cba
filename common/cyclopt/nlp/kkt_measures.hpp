#pragma once
// The optimality measures both solvers report in SolverSummary (same definitions, so their
// summaries compare): constraint violation and the Lagrangian gradient with the sign convention
//   grad L = grad f + J_eq' y_eq + J_in' y_in + nu   (y_in >= 0 for c_in <= 0; nu > 0 at upper bounds).

#include "cyclopt/nlp/problem.hpp"

#include <Eigen/Core>

namespace cyclopt::nlp {

// max(|c_eq|_inf, max(c_in, 0), bound violation); 0 for an unconstrained problem.
double constraint_violation(const Evaluation& e, const Eigen::VectorXd& x, const Eigen::VectorXd& lower,
                            const Eigen::VectorXd& upper);

// Needs an evaluation with derivatives. bound_multipliers may be empty (= 0).
Eigen::VectorXd lagrangian_gradient(const Evaluation& e, const Eigen::VectorXd& equality_multipliers,
                                    const Eigen::VectorXd& inequality_multipliers, const Eigen::VectorXd& bound_multipliers);

// The same with multipliers sigma_s of the kinked terms near their kink (kinked_terms.hpp) in place
// of the slopes a_s the gradient took there:  ... + sum_s (sigma_s - a_s) grad p_s. With sigma_s
// in [0, w_s] an element of the Clarke generalised gradient of the Lagrangian (issue 52); with
// sigma fixed, the gradient of a smooth Lagrangian whose differences give the Hessian model of the
// kinked terms' curvature.
Eigen::VectorXd lagrangian_gradient(const Evaluation& e, const Eigen::VectorXd& equality_multipliers,
                                    const Eigen::VectorXd& inequality_multipliers, const Eigen::VectorXd& bound_multipliers,
                                    const NearKinks& kinks, const Eigen::VectorXd& kink_multipliers);

}  // namespace cyclopt::nlp
