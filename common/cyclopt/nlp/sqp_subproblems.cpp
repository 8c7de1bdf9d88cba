#include "cyclopt/nlp/sqp_subproblems.hpp"

#include <limits>
#include <vector>

namespace cyclopt::nlp {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// (6.13)/(6.14) share everything but the objective in d, the slack weight and the box on d.
// Slacks t exist for the inequalities listed in `elastic` (in that order).
qp::QuadraticProgram elastic_program(const LinearisationPoint& at, const MatrixXd& d_hessian, const VectorXd& d_gradient,
                                     double slack_weight, const VectorXd& d_lower, const VectorXd& d_upper,
                                     const std::vector<int>& elastic) {
  const Evaluation& e = at.evaluation;
  const Index n = at.x.size(), m_eq = e.equalities.size(), m_in = e.inequalities.size();
  const Index m_t = static_cast<Index>(elastic.size());
  const Index total = n + 2 * m_eq + m_t;  // d, r, s, t
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
  for (Index k = 0; k < m_t; ++k) qp.inequality_matrix(elastic[static_cast<size_t>(k)], n + 2 * m_eq + k) = -1.0;
  qp.inequality_rhs = -e.inequalities;
  qp.lower_bounds = VectorXd::Zero(total);
  qp.lower_bounds.head(n) = d_lower;
  qp.upper_bounds = VectorXd::Constant(total, std::numeric_limits<double>::infinity());
  qp.upper_bounds.head(n) = d_upper;
  return qp;
}

// Solves the elastic program with slacks on a growing subset of the inequalities, starting from
// the violated ones: a hard row whose multiplier exceeds the slack weight would take a slack in
// the full program, so it gets one and the QP is re-solved. At the end every hard row has a
// multiplier <= the weight, i.e. the solution is a KKT point of the program with all slacks.
qp::QpSolution solve_elastic(const LinearisationPoint& at, const MatrixXd& d_hessian, const VectorXd& d_gradient,
                             double slack_weight, const VectorXd& d_lower, const VectorXd& d_upper,
                             const qp::ActiveSetOptions& options, const qp::ScreeningOptions& screening,
                             const qp::WorkingSet& warm_start) {
  const Evaluation& e = at.evaluation;
  const Index m_in = e.inequalities.size();
  const int d_size = static_cast<int>(at.x.size());
  std::vector<int> elastic;
  std::vector<char> is_elastic(static_cast<size_t>(m_in), 0);
  for (Index i = 0; i < m_in; ++i)
    if (e.inequalities[i] > 0.0) elastic.push_back(static_cast<int>(i)), is_elastic[static_cast<size_t>(i)] = 1;
  // Warm start: the given working set for d (slack indices would be renumbered), all slacks at 0.
  qp::WorkingSet warm = warm_start;
  std::erase_if(warm.lower_bounds, [&](int j) { return j >= d_size; });
  std::erase_if(warm.upper_bounds, [&](int j) { return j >= d_size; });
  for (int j = d_size; j < d_size + 2 * static_cast<int>(e.equalities.size()) + static_cast<int>(elastic.size()); ++j)
    warm.lower_bounds.push_back(j);
  for (;;) {
    const qp::QpSolution solution = qp::solve_screened(
        elastic_program(at, d_hessian, d_gradient, slack_weight, d_lower, d_upper, elastic), options, warm, screening);
    if (solution.status != qp::QpStatus::optimal) return solution;
    bool grown = false;
    warm = solution.working_set;  // new slacks are appended (at 0): earlier indices stay valid
    const double limit = slack_weight * (1.0 + options.optimality_tolerance) + options.optimality_tolerance;
    for (Index i = 0; i < m_in; ++i)
      if (!is_elastic[static_cast<size_t>(i)] && solution.inequality_multipliers[i] > limit) {
        elastic.push_back(static_cast<int>(i));
        is_elastic[static_cast<size_t>(i)] = 1;
        warm.lower_bounds.push_back(d_size + 2 * static_cast<int>(e.equalities.size()) + static_cast<int>(elastic.size()) - 1);
        grown = true;
      }
    if (!grown) return solution;
  }
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

KinkedSubproblem kinked_sqp_subproblem(const LinearisationPoint& at, const MatrixXd& W, const NearKinks& kinks) {
  const KinkedTerms& k = at.evaluation.kinks;
  KinkedSubproblem s{sqp_subproblem(at, W), {kink_jacobian(k, kinks), -k.values(kinks.samples), kinks.weights}};
  s.qp.gradient -= s.terms.matrix.transpose() * kinks.slopes;
  return s;
}

qp::QpSolution solve_l1_relaxed_subproblem(const LinearisationPoint& at, const MatrixXd& W, double mu,
                                          const qp::ActiveSetOptions& options, const qp::ScreeningOptions& screening,
                                          const qp::WorkingSet& warm_start) {
  return solve_elastic(at, W, at.evaluation.gradient, mu, at.lower - at.x, at.upper - at.x, options, screening, warm_start);
}

qp::QpSolution solve_l1_feasibility_lp(const LinearisationPoint& at, double trust_radius, const qp::ActiveSetOptions& options,
                                      const qp::ScreeningOptions& screening) {
  const Index n = at.x.size();
  return solve_elastic(at, MatrixXd::Zero(n, n), VectorXd::Zero(n), 1.0, (at.lower - at.x).cwiseMax(-trust_radius),
                       (at.upper - at.x).cwiseMin(trust_radius), options, screening, {});
}

}  // namespace cyclopt::nlp
