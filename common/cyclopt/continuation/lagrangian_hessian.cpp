#include "cyclopt/continuation/lagrangian_hessian.hpp"

#include "cyclopt/nlp/cached_evaluator.hpp"
#include "cyclopt/nlp/parallel_columns.hpp"
#include "cyclopt/nlp/sqp_building_blocks.hpp"

#include <cmath>

namespace cyclopt::continuation {

Eigen::MatrixXd lagrangian_hessian(nlp::Problem& problem, const Eigen::VectorXd& x, const nlp::Evaluation& at,
                                   const Eigen::VectorXd& y_eq, const Eigen::VectorXd& y_in) {
  const Eigen::Index n = x.size();
  const Eigen::VectorXd lower = problem.lower_bounds(), upper = problem.upper_bounds();
  const Eigen::VectorXd g0 = nlp::lagrangian_gradient(at, y_eq, y_in, {});
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
  nlp::SolverSummary counts;
  nlp::CachedEvaluator evaluator(problem, counts);
  nlp::for_each_column(evaluator, static_cast<int>(n), [&](int j, nlp::CachedEvaluator& ev) {
    const double h = std::sqrt(1e-16) * std::max(1.0, std::abs(x[j]));  // ~ sqrt(eps): forward-difference optimum
    for (const double step : {h, -h}) {
      Eigen::VectorXd xs = x;
      xs[j] += step;
      if (xs[j] > upper[j] || xs[j] < lower[j] || !ev.evaluate(xs, true).ok) continue;
      H.col(j) = (nlp::lagrangian_gradient(ev.evaluation(), y_eq, y_in, {}) - g0) / step;
      break;
    }
    return true;  // a column without an evaluable side stays 0
  });
  return 0.5 * (H + H.transpose());
}

}  // namespace cyclopt::continuation
