#pragma once
// Hessian of the Lagrangian by forward differences of its exact (AD) gradient, for W_1 of the
// seed's SQP (seed 001 eq. (6.23); the seed uses the complex step on the gradients): n
// evaluations with derivatives, symmetrised. A point x + h e_j without a real solution is
// replaced by x - h e_j (the seed's "no real solution" rule). objective_factor sigma weights f in
// L = sigma f + y_eq' c_eq + y_in' c_in (Ipopt's eval_h asks for sigma = 0 in its restoration phase).
// With kink multipliers (issue 52) the gradient is that of kkt_measures.hpp's kinked Lagrangian: the
// curvature of the kinked terms near their kink enters through their multipliers, not through
// the slopes' jumps across the kinks.
// The columns run on two threads when a core is spare (parallel_columns.hpp).

#include "cyclopt/nlp/cached_evaluator.hpp"

#include <Eigen/Core>

#include <optional>

namespace cyclopt::nlp {

// `at` is the evaluation with derivatives at x (it is copied: the evaluator's cache is reused).
// Nothing if some column has no evaluable point on either side.
std::optional<Eigen::MatrixXd> lagrangian_hessian_by_differences(CachedEvaluator& evaluator, const Eigen::VectorXd& x,
                                                                 const Evaluation& at,
                                                                 const Eigen::VectorXd& equality_multipliers,
                                                                 const Eigen::VectorXd& inequality_multipliers,
                                                                 double objective_factor = 1.0, const NearKinks& kinks = {},
                                                                 const Eigen::VectorXd& kink_multipliers = {});

}  // namespace cyclopt::nlp
