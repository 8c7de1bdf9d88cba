#include "cyclopt/nlp/active_set_projections.hpp"

#include <Eigen/QR>

namespace cyclopt::nlp {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// Rows: all equality gradients, then the listed inequality gradients.
MatrixXd active_jacobian(const Evaluation& e, const std::vector<int>& inequalities) {
  const Index m_eq = e.equality_jacobian.rows();
  MatrixXd A(m_eq + static_cast<Index>(inequalities.size()), e.equality_jacobian.cols());
  A.topRows(m_eq) = e.equality_jacobian;
  for (size_t k = 0; k < inequalities.size(); ++k) A.row(m_eq + static_cast<Index>(k)) = e.inequality_jacobian.row(inequalities[k]);
  return A;
}

}  // namespace

LeastSquaresMultipliers least_squares_multipliers(const Evaluation& e, const ActiveConstraints& active) {
  const Index n = e.gradient.size(), m_eq = e.equalities.size(), m_in = e.inequalities.size();
  const Index m_a = static_cast<Index>(active.inequalities.size()), m_b = static_cast<Index>(active.bounds.size());
  MatrixXd At(n, m_eq + m_a + m_b);  // columns: gradients of the active constraints
  At.leftCols(m_eq + m_a) = active_jacobian(e, active.inequalities).transpose();
  At.rightCols(m_b).setZero();
  for (Index k = 0; k < m_b; ++k) At(active.bounds[static_cast<size_t>(k)], m_eq + m_a + k) = 1.0;
  LeastSquaresMultipliers y{VectorXd::Zero(m_eq), VectorXd::Zero(m_in), VectorXd::Zero(n)};
  if (At.cols() == 0) return y;
  const VectorXd solution = Eigen::CompleteOrthogonalDecomposition<MatrixXd>(At).solve(-e.gradient);
  y.equality = solution.head(m_eq);
  for (Index k = 0; k < m_a; ++k) y.inequality[active.inequalities[static_cast<size_t>(k)]] = solution[m_eq + k];
  for (Index k = 0; k < m_b; ++k) y.bound[active.bounds[static_cast<size_t>(k)]] = solution[m_eq + m_a + k];
  return y;
}

VectorXd second_order_correction(const Evaluation& trial, const std::vector<int>& active_inequalities) {
  return second_order_correction(trial, active_inequalities, {});
}

VectorXd second_order_correction(const Evaluation& trial, const std::vector<int>& active_inequalities,
                                 const std::vector<int>& held_kinks) {
  const Index m_c = trial.equalities.size() + static_cast<Index>(active_inequalities.size());
  const Index m_k = static_cast<Index>(held_kinks.size());
  MatrixXd A(m_c + m_k, trial.gradient.size());
  A.topRows(m_c) = active_jacobian(trial, active_inequalities);
  if (A.rows() == 0) return VectorXd::Zero(trial.gradient.size());
  VectorXd c(A.rows());
  c.head(trial.equalities.size()) = trial.equalities;
  for (size_t k = 0; k < active_inequalities.size(); ++k)
    c[trial.equalities.size() + static_cast<Index>(k)] = trial.inequalities[active_inequalities[k]];
  if (m_k) {
    A.bottomRows(m_k) = trial.kinks.jacobian(held_kinks, Eigen::all);
    c.tail(m_k) = trial.kinks.values(held_kinks);
  }
  // Minimum-norm solution of A d = -c: the solution of the KKT system (6.18).
  return Eigen::CompleteOrthogonalDecomposition<MatrixXd>(A).solve(-c);
}

}  // namespace cyclopt::nlp
