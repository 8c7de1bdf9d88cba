#include "cyclopt/nlp/difference_hessian.hpp"

#include "cyclopt/nlp/kkt_measures.hpp"
#include "cyclopt/nlp/parallel_columns.hpp"

#include <cmath>
#include <limits>

namespace cyclopt::nlp {

std::optional<Eigen::MatrixXd> lagrangian_hessian_by_differences(CachedEvaluator& evaluator, const Eigen::VectorXd& x,
                                                                 const Evaluation& at,
                                                                 const Eigen::VectorXd& equality_multipliers,
                                                                 const Eigen::VectorXd& inequality_multipliers,
                                                                 double objective_factor, const NearKinks& kinks,
                                                                 const Eigen::VectorXd& kink_multipliers) {
  const Eigen::Index n = x.size();
  auto gradient = [&](const Evaluation& e) {
    Eigen::VectorXd g = objective_factor * lagrangian_gradient(e, {}, {}, {}, kinks, kink_multipliers);
    if (equality_multipliers.size()) g += e.equality_jacobian.transpose() * equality_multipliers;
    if (inequality_multipliers.size()) g += e.inequality_jacobian.transpose() * inequality_multipliers;
    return g;
  };
  const Eigen::VectorXd base = gradient(at);
  Eigen::MatrixXd H(n, n);
  const bool all_columns = for_each_column(evaluator, static_cast<int>(n), [&](int j, CachedEvaluator& ev) {
    const double h = std::sqrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, std::abs(x[j]));
    for (double side : {1.0, -1.0}) {
      Eigen::VectorXd xh = x;
      xh[j] += side * h;
      if (!ev.evaluate(xh, true).ok) continue;
      H.col(j) = (gradient(ev.evaluation()) - base) / (side * h);
      return true;
    }
    return false;
  });
  if (!all_columns) return std::nullopt;
  return Eigen::MatrixXd(0.5 * (H + H.transpose()));
}

}  // namespace cyclopt::nlp
