#pragma once
// Levenberg-Marquardt for small dense nonlinear least squares, min 1/2 |r(x)|^2, with evaluation
// failures treated as rejected steps (more damping), as the walker's "no real solution" requires.
// Used to restore feasibility of starting gaits (walker/starting_gait.hpp).

#include <Eigen/Core>

#include <functional>
#include <string>

namespace cyclopt::nlp {

// Fills r (and J = dr/dx when J != nullptr) at x; returns false where x cannot be evaluated.
using ResidualFunction = std::function<bool(const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J)>;

struct LeastSquaresOptions {
  int max_iterations = 60;
  double cost_tolerance = 1e-20;      // stop when 1/2 |r|^2 falls below
  double step_tolerance = 1e-12;      // stop when |dx| <= step_tolerance (1 + |x|)
  double initial_damping = 1e-3;      // lambda, relative to max diag(J^T J)
  double max_damping = 1e12;
};

struct LeastSquaresSummary {
  bool converged = false;  // cost below cost_tolerance
  int iterations = 0;
  int evaluations = 0;
  int failed_evaluations = 0;
  double cost = 0.0;
  std::string message;
};

// x is the start on entry and the best point found on exit; the start must be evaluable.
LeastSquaresSummary levenberg_marquardt(const ResidualFunction& residual, Eigen::VectorXd& x,
                                        const LeastSquaresOptions& options = {});

}  // namespace cyclopt::nlp
