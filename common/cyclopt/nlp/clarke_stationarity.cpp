#include "cyclopt/nlp/clarke_stationarity.hpp"

#include "cyclopt/nlp/kkt_measures.hpp"
#include "cyclopt/qp/bounded_least_squares.hpp"

#include <limits>

namespace cyclopt::nlp {

ClarkeMultipliers clarke_multipliers(const Evaluation& e, const ActiveConstraints& active, const NearKinks& kinks,
                                     const Eigen::VectorXd& x, const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                     double bound_tolerance) {
  using Eigen::Index;
  constexpr double inf = std::numeric_limits<double>::infinity();
  const Index n = e.gradient.size(), m_eq = e.equalities.size(), m_in = e.inequalities.size();
  const Index m_a = static_cast<Index>(active.inequalities.size()), m_b = static_cast<Index>(active.bounds.size());
  const Index m_k = kinks.size();
  // Columns: equality gradients, active inequality gradients, unit vectors of active bounds, kink gradients.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, m_eq + m_a + m_b + m_k);
  Eigen::VectorXd lo(A.cols()), hi(A.cols());
  A.leftCols(m_eq) = e.equality_jacobian.transpose();
  lo.head(m_eq).setConstant(-inf);
  hi.head(m_eq).setConstant(inf);
  for (Index k = 0; k < m_a; ++k) {
    A.col(m_eq + k) = e.inequality_jacobian.row(active.inequalities[static_cast<size_t>(k)]).transpose();
    lo[m_eq + k] = 0.0;
    hi[m_eq + k] = inf;
  }
  for (Index k = 0; k < m_b; ++k) {
    const int j = active.bounds[static_cast<size_t>(k)];
    const Index c = m_eq + m_a + k;
    A(j, c) = 1.0;
    lo[c] = x[j] <= lower[j] + bound_tolerance ? -inf : 0.0;
    hi[c] = x[j] >= upper[j] - bound_tolerance ? inf : 0.0;
  }
  if (m_k) {
    A.rightCols(m_k) = kink_jacobian(e.kinks, kinks).transpose();
    lo.tail(m_k).setZero();
    hi.tail(m_k) = kinks.weights;
  }
  // r = g_smooth + A lambda with g_smooth = grad f - sum a_s grad p_s.
  Eigen::VectorXd g_smooth = e.gradient;
  if (m_k) g_smooth -= A.rightCols(m_k) * kinks.slopes;
  const qp::BoundedLeastSquaresSolution ls = qp::solve_bounded_least_squares(A, -g_smooth, lo, hi);
  ClarkeMultipliers out{Eigen::VectorXd::Zero(m_eq), Eigen::VectorXd::Zero(m_in), Eigen::VectorXd::Zero(n), kinks,
                        ls.x.tail(m_k), 0.0};
  out.equality = ls.x.head(m_eq);
  for (Index k = 0; k < m_a; ++k) out.inequality[active.inequalities[static_cast<size_t>(k)]] = ls.x[m_eq + k];
  for (Index k = 0; k < m_b; ++k) out.bound[active.bounds[static_cast<size_t>(k)]] = ls.x[m_eq + m_a + k];
  out.residual = lagrangian_gradient(e, out.equality, out.inequality, out.bound, kinks, out.kink).lpNorm<Eigen::Infinity>();
  return out;
}

}  // namespace cyclopt::nlp
