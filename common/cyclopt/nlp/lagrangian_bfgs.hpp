#pragma once
// Dense damped-BFGS approximation of the Hessian of the Lagrangian, fed from successive points
// with derivatives: the SQP's quasi-Newton matrix (damped_bfgs.hpp, seed 001 eqs. 6.20-6.25) for
// Ipopt's exact-Hessian interface (eval_h). For the walker (n = 20-30) a full matrix is cheap,
// stays positive definite under nonconvex curvature (Powell damping instead of Ipopt's L-BFGS
// skipping of updates with s'y <= 0) and keeps the curvature of every step, not only the last few.

#include "cyclopt/nlp/problem.hpp"

#include <Eigen/Core>

namespace cyclopt::nlp {

class LagrangianBfgs {
 public:
  explicit LagrangianBfgs(int num_variables);

  // W for the Lagrangian sigma f + y_eq' c_eq + y_in' c_in at x (`at`: evaluation with
  // derivatives at x). A new x updates W with s = x - x_prev and y = the change of the
  // Lagrangian gradient at the current multipliers (6.20); the first update scales the identity
  // (6.25). sigma = 0 (Ipopt's restoration phase) approximates the constraints' curvature only:
  // keep a separate instance for it, so that it does not overwrite that of the optimality problem.
  // Replaces W by a given positive definite matrix (e.g. (6.24) of a difference Hessian); later
  // points update it by (6.22) directly, without the identity scaling (6.25).
  void reset(const Eigen::MatrixXd& W);

  const Eigen::MatrixXd& at(const Eigen::VectorXd& x, const Evaluation& e, double sigma,
                            const Eigen::VectorXd& equality_multipliers, const Eigen::VectorXd& inequality_multipliers);

 private:
  Eigen::MatrixXd W_;
  bool has_previous_ = false;
  bool updated_ = false;
  Eigen::VectorXd x_previous_;
  Evaluation previous_;  // gradient and Jacobians at x_previous_
};

}  // namespace cyclopt::nlp
