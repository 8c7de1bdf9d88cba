#include "cyclopt/continuation/lagrangian_hessian.hpp"

#include "cyclopt/nlp/sqp_building_blocks.hpp"

#include <cmath>

namespace cyclopt::continuation {

Eigen::MatrixXd lagrangian_hessian(nlp::Problem& problem, const Eigen::VectorXd& x, const nlp::Evaluation& at,
                                   const Eigen::VectorXd& y_eq, const Eigen::VectorXd& y_in) {
  const Eigen::Index n = x.size();
  const Eigen::VectorXd lower = problem.lower_bounds(), upper = problem.upper_bounds();
  const Eigen::VectorXd g0 = nlp::lagrangian_gradient(at, y_eq, y_in, {});
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
  nlp::Evaluation e;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double h = std::sqrt(1e-16) * std::max(1.0, std::abs(x[j]));  // ~ sqrt(eps): forward-difference optimum
    for (const double step : {h, -h}) {
      Eigen::VectorXd xs = x;
      xs[j] += step;
      if (xs[j] > upper[j] || xs[j] < lower[j] || !problem.evaluate(xs, true, e).ok || !e.gradient.allFinite()) continue;
      H.col(j) = (nlp::lagrangian_gradient(e, y_eq, y_in, {}) - g0) / step;
      break;
    }
  }
  return 0.5 * (H + H.transpose());
}

}  // namespace cyclopt::continuation
