#include "cyclopt/nlp/levenberg_marquardt.hpp"

#include <Eigen/Cholesky>

#include <algorithm>

namespace cyclopt::nlp {

LeastSquaresSummary levenberg_marquardt(const ResidualFunction& residual, Eigen::VectorXd& x,
                                        const LeastSquaresOptions& o) {
  LeastSquaresSummary s;
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  ++s.evaluations;
  if (!residual(x, r, &J)) {
    ++s.failed_evaluations;
    s.message = "start point cannot be evaluated";
    return s;
  }
  s.cost = 0.5 * r.squaredNorm();
  double lambda = -1.0;
  Eigen::VectorXd r_trial;
  for (s.iterations = 0; s.iterations < o.max_iterations; ++s.iterations) {
    if (s.cost <= o.cost_tolerance) break;
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    if (lambda < 0.0) lambda = o.initial_damping * std::max(JtJ.diagonal().maxCoeff(), 1e-12);
    bool accepted = false;
    while (!accepted && lambda <= o.max_damping) {
      Eigen::MatrixXd A = JtJ;
      A.diagonal() += lambda * (JtJ.diagonal().array() + 1e-12).matrix();
      const Eigen::VectorXd dx = -A.ldlt().solve(g);
      if (dx.norm() <= o.step_tolerance * (1.0 + x.norm())) {
        s.message = "step below tolerance";
        s.converged = s.cost <= o.cost_tolerance;
        return s;
      }
      const Eigen::VectorXd x_trial = x + dx;
      ++s.evaluations;
      const bool ok = residual(x_trial, r_trial, nullptr);
      if (!ok) ++s.failed_evaluations;
      if (ok && 0.5 * r_trial.squaredNorm() < s.cost) {
        x = x_trial;
        ++s.evaluations;
        residual(x, r, &J);
        s.cost = 0.5 * r.squaredNorm();
        lambda = std::max(lambda / 3.0, 1e-15);
        accepted = true;
      } else {
        lambda *= 4.0;
      }
    }
    if (!accepted) {
      s.message = "no decrease at maximal damping";
      break;
    }
  }
  s.converged = s.cost <= o.cost_tolerance;
  if (s.message.empty()) s.message = s.converged ? "converged" : "iteration limit";
  return s;
}

}  // namespace cyclopt::nlp
