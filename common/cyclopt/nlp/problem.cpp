#include "cyclopt/nlp/problem.hpp"

#include <limits>

namespace cyclopt::nlp {

Eigen::VectorXd Problem::lower_bounds() const {
  return Eigen::VectorXd::Constant(num_variables(), -std::numeric_limits<double>::infinity());
}

Eigen::VectorXd Problem::upper_bounds() const {
  return Eigen::VectorXd::Constant(num_variables(), std::numeric_limits<double>::infinity());
}

std::unique_ptr<Problem> Problem::clone() const { return nullptr; }

std::string Problem::variable_name(int i) const { return "x[" + std::to_string(i) + "]"; }

std::string Problem::constraint_name(bool equality, int i) const {
  return (equality ? "c_eq[" : "c_in[") + std::to_string(i) + "]";
}

}  // namespace cyclopt::nlp
