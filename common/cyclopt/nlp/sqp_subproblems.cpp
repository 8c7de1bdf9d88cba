#include "cyclopt/nlp/sqp_subproblems.hpp"

#include <limits>

namespace cyclopt::nlp {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// (6.13)/(6.14) share everything but the objective in d, the slack weight and the box on d.
qp::QuadraticProgram elastic_program(const LinearisationPoint& at, const MatrixXd& d_hessian, const VectorXd& d_gradient,
                                     double slack_weight, const VectorXd& d_lower, const VectorXd& d_upper) {
  const Evaluation& e = at.evaluation;
  const Index n = at.x.size(), m_eq = e.equalities.size(), m_in = e.inequalities.size();
  const Index total = n + 2 * m_eq + m_in;  // d, r, s, t
  qp::QuadraticProgram qp;
  qp.hessian = MatrixXd::Zero(total, total);
  qp.hessian.topLeftCorner(n, n) = d_hessian;
  qp.gradient = VectorXd::Constant(total, slack_weight);
  qp.gradient.head(n) = d_gradient;
  qp.equality_matrix = MatrixXd::Zero(m_eq, total);  // J_g d - r + s = -c_g
  qp.equality_matrix.leftCols(n) = e.equality_jacobian;
  qp.equality_matrix.middleCols(n, m_eq) = -MatrixXd::Identity(m_eq, m_eq);
  qp.equality_matrix.middleCols(n + m_eq, m_eq) = MatrixXd::Identity(m_eq, m_eq);
  qp.equality_rhs = -e.equalities;
  qp.inequality_matrix = MatrixXd::Zero(m_in, total);  // J_u d - t <= -c_u
  qp.inequality_matrix.leftCols(n) = e.inequality_jacobian;
  qp.inequality_matrix.rightCols(m_in) = -MatrixXd::Identity(m_in, m_in);
  qp.inequality_rhs = -e.inequalities;
  qp.lower_bounds = VectorXd::Zero(total);
  qp.lower_bounds.head(n) = d_lower;
  qp.upper_bounds = VectorXd::Constant(total, std::numeric_limits<double>::infinity());
  qp.upper_bounds.head(n) = d_upper;
  return qp;
}

}  // namespace

qp::QuadraticProgram sqp_subproblem(const LinearisationPoint& at, const MatrixXd& W) {
  const Evaluation& e = at.evaluation;
  qp::QuadraticProgram qp;
  qp.hessian = W;
  qp.gradient = e.gradient;
  qp.equality_matrix = e.equality_jacobian;
  qp.equality_rhs = -e.equalities;
  qp.inequality_matrix = e.inequality_jacobian;
  qp.inequality_rhs = -e.inequalities;
  qp.lower_bounds = at.lower - at.x;
  qp.upper_bounds = at.upper - at.x;
  return qp;
}

qp::QuadraticProgram l1_relaxed_subproblem(const LinearisationPoint& at, const MatrixXd& W, double mu) {
  return elastic_program(at, W, at.evaluation.gradient, mu, at.lower - at.x, at.upper - at.x);
}

qp::QuadraticProgram l1_feasibility_lp(const LinearisationPoint& at, double trust_radius) {
  const Index n = at.x.size();
  return elastic_program(at, MatrixXd::Zero(n, n), VectorXd::Zero(n), 1.0,
                         (at.lower - at.x).cwiseMax(-trust_radius), (at.upper - at.x).cwiseMin(trust_radius));
}

}  // namespace cyclopt::nlp
