#include "cyclopt/nlp/kkt_measures.hpp"

#include <algorithm>

namespace cyclopt::nlp {

double constraint_violation(const Evaluation& e, const Eigen::VectorXd& x, const Eigen::VectorXd& lower,
                            const Eigen::VectorXd& upper) {
  double v = 0.0;
  if (e.equalities.size()) v = std::max(v, e.equalities.lpNorm<Eigen::Infinity>());
  if (e.inequalities.size()) v = std::max(v, e.inequalities.maxCoeff());
  if (x.size()) v = std::max({v, (lower - x).maxCoeff(), (x - upper).maxCoeff()});
  return v;
}

Eigen::VectorXd lagrangian_gradient(const Evaluation& e, const Eigen::VectorXd& equality_multipliers,
                                    const Eigen::VectorXd& inequality_multipliers, const Eigen::VectorXd& bound_multipliers) {
  Eigen::VectorXd g = e.gradient;
  if (equality_multipliers.size()) g += e.equality_jacobian.transpose() * equality_multipliers;
  if (inequality_multipliers.size()) g += e.inequality_jacobian.transpose() * inequality_multipliers;
  if (bound_multipliers.size()) g += bound_multipliers;
  return g;
}

Eigen::VectorXd lagrangian_gradient(const Evaluation& e, const Eigen::VectorXd& equality_multipliers,
                                    const Eigen::VectorXd& inequality_multipliers, const Eigen::VectorXd& bound_multipliers,
                                    const NearKinks& kinks, const Eigen::VectorXd& kink_multipliers) {
  Eigen::VectorXd g = lagrangian_gradient(e, equality_multipliers, inequality_multipliers, bound_multipliers);
  if (!kinks.empty()) g += kink_jacobian(e.kinks, kinks).transpose() * (kink_multipliers - kink_slopes(e.kinks, kinks));
  return g;
}

}  // namespace cyclopt::nlp
