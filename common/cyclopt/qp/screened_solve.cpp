#include "cyclopt/qp/screened_solve.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cyclopt::qp {
namespace {

using Eigen::Index;

QuadraticProgram with_rows(const QuadraticProgram& qp, const std::vector<int>& rows) {
  QuadraticProgram reduced = qp;
  reduced.inequality_matrix = qp.inequality_matrix(rows, Eigen::all);
  reduced.inequality_rhs = qp.inequality_rhs(rows);
  return reduced;
}

}  // namespace

QpSolution solve_screened(const QuadraticProgram& qp, const ActiveSetOptions& options, const WorkingSet& warm_start,
                          const ScreeningOptions& screening) {
  const Index m_in = qp.inequality_matrix.rows();
  std::vector<char> kept(static_cast<size_t>(m_in), 0);
  for (int i : warm_start.inequalities)
    if (i >= 0 && i < m_in) kept[static_cast<size_t>(i)] = 1;
  for (Index i = 0; i < m_in; ++i)
    if (qp.inequality_rhs[i] <= screening.margin * std::max(1.0, qp.inequality_matrix.row(i).norm()))
      kept[static_cast<size_t>(i)] = 1;
  WorkingSet warm = warm_start;
  int iterations = 0;
  for (;;) {
    std::vector<int> rows;  // reduced row k is full row rows[k]
    std::vector<int> position(static_cast<size_t>(m_in), -1);
    for (Index i = 0; i < m_in; ++i)
      if (kept[static_cast<size_t>(i)]) position[static_cast<size_t>(i)] = static_cast<int>(rows.size()), rows.push_back(static_cast<int>(i));
    WorkingSet reduced_warm = warm;
    reduced_warm.inequalities.clear();
    for (int i : warm.inequalities)
      if (i >= 0 && i < m_in && position[static_cast<size_t>(i)] >= 0) reduced_warm.inequalities.push_back(position[static_cast<size_t>(i)]);
    if (static_cast<Index>(rows.size()) == m_in) {
      QpSolution full = solve_active_set(qp, options, warm);
      full.iterations += iterations;
      return full;
    }
    QpSolution s = solve_active_set(with_rows(qp, rows), options, reduced_warm);
    iterations += s.iterations;
    s.iterations = iterations;
    for (int& i : s.working_set.inequalities) i = rows[static_cast<size_t>(i)];
    if (s.status == QpStatus::unbounded) {
      std::fill(kept.begin(), kept.end(), 1);
      warm = s.working_set;
      continue;
    }
    Eigen::VectorXd multipliers = Eigen::VectorXd::Zero(m_in);
    multipliers(rows) = s.inequality_multipliers;
    s.inequality_multipliers = multipliers;
    if (s.status != QpStatus::optimal) return s;  // infeasible (then so is the full QP) or max_iterations
    const Eigen::VectorXd residual = qp.inequality_matrix * s.x - qp.inequality_rhs;
    bool grown = false;
    for (Index i = 0; i < m_in; ++i)
      if (!kept[static_cast<size_t>(i)] && residual[i] > options.feasibility_tolerance) kept[static_cast<size_t>(i)] = 1, grown = true;
    if (!grown) return s;
    warm = s.working_set;
  }
}

}  // namespace cyclopt::qp
