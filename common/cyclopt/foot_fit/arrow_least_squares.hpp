#pragma once
// Bounded Levenberg-Marquardt for least squares whose Jacobian has the "arrow" structure of the
// fits of seed 001 (4.16) / (4.21): each local unknown (a foot angle theta_F,k,j) enters only its
// own pair of residuals, while a few global unknowns (the shape parameters and the offsets
// x_off,k) enter many. The damped normal equations are solved by eliminating the locals (one
// scalar each) and factorising the small Schur complement of the globals, so an iteration costs
// O(N G^2) for N samples and G globals instead of O((N + G)^3).
//
// Bounds act on the globals (equal bounds fix a parameter). A step is projected onto the box;
// parameters on a bound whose gradient points outwards are held for the iteration.

#include <Eigen/Core>

#include <functional>
#include <string>

namespace cyclopt::foot_fit {

// Residuals and Jacobian blocks at (global, local): residual pair j is r.col(j); its derivative
// by local j is local_jacobian.col(j), by the globals rows 2j, 2j+1 of global_jacobian.
struct ArrowEvaluation {
  Eigen::Matrix2Xd r;
  Eigen::Matrix2Xd local_jacobian;
  Eigen::MatrixXd global_jacobian;  // 2N x G
};

// Fills `out` (the Jacobian blocks only when `with_jacobian`); returns false when the point
// cannot be evaluated (the step is then rejected).
using ArrowResidual = std::function<bool(const Eigen::VectorXd& global, const Eigen::VectorXd& local, bool with_jacobian,
                                         ArrowEvaluation& out)>;

struct ArrowOptions {
  int max_iterations = 200;
  double function_tolerance = 1e-10;  // converged when the undamped Gauss-Newton step promises < this * cost
  double step_tolerance = 1e-12;      // ... or the scaled step < this
  double zero_cost = 1e-28;           // ... or 1/2 |r|^2 below this (exact data)
  // ... or the undamped Gauss-Newton step moves no free global by this many of its standard
  // errors (sigma^2 S^-1, sigma^2 = |r|^2 / (residuals - unknowns)), so iterating on cannot change
  // a reported parameter by more than that share of its uncertainty. Near a sharp transition
  // (k -> 0) the Gauss-Newton model is poor and the decrease tests above take thousands of
  // iterations for changes in the seventh digit of the cost; cyclopt-foot fit uses 1e-2 on real
  // recordings. 0 (the default) disables the test, so foot_fit jobs stop by the decrease tests.
  double parameter_tolerance = 0.0;
  double initial_damping = 1e-4;      // relative to the diagonal of J^T J
  double max_damping = 1e14;
};

struct ArrowSummary {
  bool converged = false;
  int iterations = 0;
  int evaluations = 0;
  double initial_cost = 0.0;
  double cost = 0.0;  // 1/2 |r|^2 at the solution
  std::string message;
  // Undamped reduced normal matrix of the globals at the solution (the Schur complement of
  // J^T J), whose inverse times sigma^2 is the globals' covariance; rows/columns of globals held
  // on a bound or fixed are zero.
  Eigen::MatrixXd reduced_normal_matrix;
  Eigen::Array<bool, Eigen::Dynamic, 1> free;  // globals not fixed or held on a bound at the end
};

// global and local hold the start on entry and the solution on exit. The start is projected
// onto the bounds; it must be evaluable.
ArrowSummary solve_arrow_least_squares(const ArrowResidual& residual, Eigen::VectorXd& global, Eigen::VectorXd& local,
                                       const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                       const ArrowOptions& options = {});

}  // namespace cyclopt::foot_fit
