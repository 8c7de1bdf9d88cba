#include "cyclopt/qp/quadratic_program.hpp"

#include <stdexcept>
#include <string>

namespace cyclopt::qp {
namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("QuadraticProgram." + message);
}

std::string dims(Eigen::Index rows, Eigen::Index cols) {
  return std::to_string(rows) + " x " + std::to_string(cols);
}

}  // namespace

void validate(const QuadraticProgram& qp) {
  const Eigen::Index n = qp.num_variables();
  require(qp.hessian.rows() == n && qp.hessian.cols() == n,
          "hessian: must be n x n = " + dims(n, n) + " (n = gradient size), got " + dims(qp.hessian.rows(), qp.hessian.cols()));
  require(qp.equality_matrix.cols() == n || qp.equality_matrix.size() == 0,
          "equality_matrix: must have n = " + std::to_string(n) + " columns");
  require(qp.equality_matrix.rows() == qp.equality_rhs.size(),
          "equality_rhs: size must equal equality_matrix rows (" + std::to_string(qp.equality_matrix.rows()) + ")");
  require(qp.inequality_matrix.cols() == n || qp.inequality_matrix.size() == 0,
          "inequality_matrix: must have n = " + std::to_string(n) + " columns");
  require(qp.inequality_matrix.rows() == qp.inequality_rhs.size(),
          "inequality_rhs: size must equal inequality_matrix rows (" + std::to_string(qp.inequality_matrix.rows()) + ")");
  require(qp.lower_bounds.size() == 0 || qp.lower_bounds.size() == n,
          "lower_bounds: size must be 0 or n = " + std::to_string(n));
  require(qp.upper_bounds.size() == 0 || qp.upper_bounds.size() == n,
          "upper_bounds: size must be 0 or n = " + std::to_string(n));
  require(qp.hessian.allFinite() && qp.gradient.allFinite(), "hessian/gradient: must be finite");
  require(qp.equality_matrix.allFinite() && qp.equality_rhs.allFinite(), "equality_matrix/equality_rhs: must be finite");
  require(qp.inequality_matrix.allFinite() && qp.inequality_rhs.allFinite(),
          "inequality_matrix/inequality_rhs: must be finite");
  require(!qp.lower_bounds.hasNaN() && !qp.upper_bounds.hasNaN(), "lower_bounds/upper_bounds: must not be NaN");
  if (qp.lower_bounds.size() == n && qp.upper_bounds.size() == n) {
    for (Eigen::Index i = 0; i < n; ++i)
      require(qp.lower_bounds[i] <= qp.upper_bounds[i],
              "lower_bounds[" + std::to_string(i) + "]: must be <= upper_bounds[" + std::to_string(i) + "]");
  }
}

}  // namespace cyclopt::qp
