#include "cyclopt/nlp/l1_merit.hpp"

#include <algorithm>

namespace cyclopt::nlp {
namespace {

double weighted_violation(const Eigen::VectorXd& eq, const Eigen::VectorXd& in, const Penalties& mu) {
  return mu.equality.dot(eq.cwiseAbs()) + mu.inequality.dot(in.cwiseMax(0.0));
}

}  // namespace

double Penalties::max() const {
  double m = 0.0;
  if (equality.size()) m = std::max(m, equality.maxCoeff());
  if (inequality.size()) m = std::max(m, inequality.maxCoeff());
  return m;
}

Penalties Penalties::uniform(double mu, Eigen::Index m_eq, Eigen::Index m_in) {
  return {Eigen::VectorXd::Constant(m_eq, mu), Eigen::VectorXd::Constant(m_in, mu)};
}

double l1_merit(const Evaluation& e, const Penalties& mu) {
  return e.objective + weighted_violation(e.equalities, e.inequalities, mu);
}

double linearized_violation(const Evaluation& e, const Eigen::VectorXd& d) {
  return (e.equality_jacobian * d + e.equalities).cwiseAbs().sum() +
         (e.inequality_jacobian * d + e.inequalities).cwiseMax(0.0).sum();
}

double l1_model(const Evaluation& e, const Eigen::MatrixXd& W, const Eigen::VectorXd& d, const Penalties& mu) {
  return e.objective + e.gradient.dot(d) + 0.5 * d.dot(W * d) +
         weighted_violation(e.equality_jacobian * d + e.equalities, e.inequality_jacobian * d + e.inequalities, mu);
}

double l1_model(const Evaluation& e, const Eigen::MatrixXd& W, const Eigen::VectorXd& d, const Penalties& mu,
                const NearKinks& kinks) {
  if (kinks.empty()) return l1_model(e, W, d, mu);
  const Eigen::MatrixXd Jk = kink_jacobian(e.kinks, kinks);
  const Eigen::VectorXd p = e.kinks.values(kinks.samples);
  const double kinked = kinks.weights.dot((p + Jk * d).cwiseMax(0.0) - p.cwiseMax(0.0));
  return l1_model(e, W, d, mu) - kinks.slopes.dot(Jk * d) + kinked;
}

}  // namespace cyclopt::nlp
