#include "cyclopt/nlp/lagrangian_bfgs.hpp"

#include "cyclopt/nlp/damped_bfgs.hpp"

namespace cyclopt::nlp {

LagrangianBfgs::LagrangianBfgs(int num_variables) : W_(Eigen::MatrixXd::Identity(num_variables, num_variables)) {}

void LagrangianBfgs::reset(const Eigen::MatrixXd& W) {
  W_ = W;
  updated_ = true;
}

const Eigen::MatrixXd& LagrangianBfgs::at(const Eigen::VectorXd& x, const Evaluation& e, double sigma,
                                          const Eigen::VectorXd& equality_multipliers,
                                          const Eigen::VectorXd& inequality_multipliers) {
  if (has_previous_ && x == x_previous_) return W_;
  if (has_previous_) {
    const Eigen::VectorXd s = x - x_previous_;
    Eigen::VectorXd y = sigma * (e.gradient - previous_.gradient);
    if (equality_multipliers.size()) y += (e.equality_jacobian - previous_.equality_jacobian).transpose() * equality_multipliers;
    if (inequality_multipliers.size())
      y += (e.inequality_jacobian - previous_.inequality_jacobian).transpose() * inequality_multipliers;
    if (updated_) {
      damped_bfgs_update(W_, s, y);  // (6.22)
    } else {
      W_ = scaled_identity_update(s, y);  // (6.25)
      updated_ = true;
    }
  }
  has_previous_ = true;
  x_previous_ = x;
  previous_.gradient = e.gradient;
  previous_.equality_jacobian = e.equality_jacobian;
  previous_.inequality_jacobian = e.inequality_jacobian;
  return W_;
}

}  // namespace cyclopt::nlp
