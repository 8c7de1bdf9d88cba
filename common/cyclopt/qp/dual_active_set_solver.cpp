#include "cyclopt/qp/dual_active_set_solver.hpp"

#include "cyclopt/qp/working_set_refinement.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/QR>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace cyclopt::qp {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The new normal counts as linearly dependent on the working set if its part outside the span
// (in the metric of H^-1) is below this fraction of the whole.
constexpr double kDependenceTolerance = 1e-10;

// Every constraint as a row a'x <= b (equalities: a'x = b); bounds become unit rows.
enum class RowKind { equality, inequality, upper_bound, lower_bound };
struct Row {
  RowKind kind;
  int index;  // row of A_eq / A_in, or variable
};

struct Rows {
  MatrixXd a;  // one constraint per row
  VectorXd b;
  std::vector<Row> origin;
  VectorXd norms;
};

Rows stack_rows(const QuadraticProgram& qp) {
  const Index n = qp.num_variables();
  std::vector<Row> origin;
  for (Index i = 0; i < qp.equality_matrix.rows(); ++i) origin.push_back({RowKind::equality, static_cast<int>(i)});
  for (Index i = 0; i < qp.inequality_matrix.rows(); ++i) origin.push_back({RowKind::inequality, static_cast<int>(i)});
  for (Index j = 0; j < qp.upper_bounds.size(); ++j)
    if (std::isfinite(qp.upper_bounds[j])) origin.push_back({RowKind::upper_bound, static_cast<int>(j)});
  for (Index j = 0; j < qp.lower_bounds.size(); ++j)
    if (std::isfinite(qp.lower_bounds[j])) origin.push_back({RowKind::lower_bound, static_cast<int>(j)});
  const Index m = static_cast<Index>(origin.size()), m_eq = qp.equality_matrix.rows(), m_in = qp.inequality_matrix.rows();
  Rows r{MatrixXd::Zero(m, n), VectorXd(m), origin, VectorXd()};
  if (m_eq) r.a.topRows(m_eq) = qp.equality_matrix, r.b.head(m_eq) = qp.equality_rhs;
  if (m_in) r.a.middleRows(m_eq, m_in) = qp.inequality_matrix, r.b.segment(m_eq, m_in) = qp.inequality_rhs;
  for (Index k = m_eq + m_in; k < m; ++k) {
    const Row& o = origin[static_cast<size_t>(k)];
    const bool upper = o.kind == RowKind::upper_bound;
    r.a(k, o.index) = upper ? 1.0 : -1.0;
    r.b[k] = upper ? qp.upper_bounds[o.index] : -qp.lower_bounds[o.index];
  }
  r.norms = r.a.rowwise().norm();
  return r;
}

// The working set in Goldfarb-Idnani's form: normals n_j = -sign_j a_j (the direction in which
// constraint j's slack sign_j (b_j - a_j'x) grows), multipliers u_j with H x + g = sum u_j n_j,
// and with L^-1 N = Q R the matrices J = L^-T Q and R.
class WorkingSetFactorization {
 public:
  WorkingSetFactorization(const MatrixXd& L, Index n) : L_(L), n_(n) { refactor(); }

  void add(int row, double sign, const VectorXd& normal, double multiplier) {
    rows_.push_back(row), signs_.push_back(sign), u_.conservativeResize(u_.size() + 1), u_[u_.size() - 1] = multiplier;
    normals_.push_back(normal);
    refactor();
  }
  void drop(Index k) {
    rows_.erase(rows_.begin() + k), signs_.erase(signs_.begin() + k), normals_.erase(normals_.begin() + k);
    for (Index i = k; i + 1 < u_.size(); ++i) u_[i] = u_[i + 1];
    u_.conservativeResize(u_.size() - 1);
    refactor();
  }

  Index size() const { return static_cast<Index>(rows_.size()); }
  int row(Index k) const { return rows_[static_cast<size_t>(k)]; }
  double sign(Index k) const { return signs_[static_cast<size_t>(k)]; }
  const VectorXd& normal(Index k) const { return normals_[static_cast<size_t>(k)]; }
  VectorXd& multipliers() { return u_; }

  // For a new normal: the primal step z = J2 J2' n (zero if n is dependent on the working set)
  // and the change r = R^-1 J1' n of the working multipliers per unit of the new multiplier.
  struct Directions {
    VectorXd z, r;
    bool dependent;
  };
  Directions directions(const VectorXd& normal) const {
    const Index q = size();
    const VectorXd d = J_.transpose() * normal;
    Directions out{J_.rightCols(n_ - q) * d.tail(n_ - q), VectorXd(q), false};
    out.dependent = d.tail(n_ - q).norm() <= kDependenceTolerance * d.norm();
    if (out.dependent) out.z.setZero();
    if (q) out.r = R_.topLeftCorner(q, q).triangularView<Eigen::Upper>().solve(d.head(q));
    return out;
  }

 private:
  void refactor() {
    const Index q = size();
    MatrixXd B(n_, q);
    for (Index k = 0; k < q; ++k) B.col(k) = normals_[static_cast<size_t>(k)];
    L_.triangularView<Eigen::Lower>().solveInPlace(B);
    MatrixXd Q = MatrixXd::Identity(n_, n_);
    if (q) {
      const Eigen::HouseholderQR<MatrixXd> qr(B);
      Q.applyOnTheLeft(qr.householderQ());
      R_ = qr.matrixQR().topRows(q).triangularView<Eigen::Upper>();
    }
    J_ = L_.transpose().triangularView<Eigen::Upper>().solve(Q);
  }

  const MatrixXd& L_;
  Index n_;
  std::vector<int> rows_;
  std::vector<double> signs_;
  std::vector<VectorXd> normals_;
  VectorXd u_;
  MatrixXd J_, R_;
};

// Iterative refinement on the final working set (working_set_refinement.hpp): the working
// normals n_j = -sign_j a_j with c_j = -sign_j b_j; every other row within the feasibility tolerance.
void refine_dual_solution(const QuadraticProgram& qp, const Rows& rows, const std::vector<char>& active, double tol,
                           WorkingSetFactorization& ws, VectorXd& x) {
  const Index n = x.size(), q = ws.size();
  if (q == 0) return;
  MatrixXd N(n, q);
  VectorXd c(q);
  for (Index k = 0; k < q; ++k) N.col(k) = ws.normal(k), c[k] = -ws.sign(k) * rows.b[ws.row(k)];
  const auto others_feasible = [&](const VectorXd& z) {
    const VectorXd slack = rows.b - rows.a * z;
    for (Index k = 0; k < rows.a.rows(); ++k)
      if (!active[static_cast<size_t>(k)] && rows.origin[static_cast<size_t>(k)].kind != RowKind::equality && slack[k] < -tol)
        return false;
    return true;
  };
  refine_on_working_set(qp.hessian, qp.gradient, N, c, others_feasible, x, ws.multipliers());
}

}  // namespace

bool is_strictly_convex(const MatrixXd& hessian, double curvature_tolerance) {
  if (hessian.rows() == 0 || hessian.rows() != hessian.cols()) return false;
  const Eigen::LLT<MatrixXd> llt(hessian);
  if (llt.info() != Eigen::Success) return false;
  const double threshold = curvature_tolerance * std::max(1.0, hessian.diagonal().cwiseAbs().maxCoeff());
  const VectorXd pivots = llt.matrixLLT().diagonal();
  return pivots.cwiseAbs2().minCoeff() >= threshold && pivots.allFinite();
}

QpSolution solve_dual_active_set(const QuadraticProgram& qp, const ActiveSetOptions& options) {
  validate(qp);
  if (!is_strictly_convex(qp.hessian, options.curvature_tolerance))
    throw std::invalid_argument("QuadraticProgram.hessian: the dual active-set method needs a positive definite Hessian");
  const Index n = qp.num_variables();
  const Rows rows = stack_rows(qp);
  const Index m_eq = qp.equality_matrix.rows();
  const Index m = rows.a.rows();
  const Eigen::LLT<MatrixXd> llt(qp.hessian);
  const MatrixXd L = llt.matrixL();
  const double tol = options.feasibility_tolerance;

  QpSolution sol;
  sol.x = llt.solve(-qp.gradient);  // the unconstrained minimiser
  WorkingSetFactorization ws(L, n);
  std::vector<char> active(static_cast<size_t>(m), 0);
  auto finish = [&](QpStatus status, std::string message) {
    sol.status = status;
    sol.message = std::move(message);
    sol.objective = qp.objective(sol.x);
    sol.equality_multipliers = VectorXd::Zero(m_eq);
    sol.inequality_multipliers = VectorXd::Zero(qp.inequality_matrix.rows());
    sol.lower_bound_multipliers = VectorXd::Zero(n);
    sol.upper_bound_multipliers = VectorXd::Zero(n);
    for (Index k = 0; k < ws.size(); ++k) {
      const Row& o = rows.origin[static_cast<size_t>(ws.row(k))];
      const double y = ws.sign(k) * ws.multipliers()[k];  // H x + g + y a = 0
      switch (o.kind) {
        case RowKind::equality: sol.equality_multipliers[o.index] = y; break;
        case RowKind::inequality:
          sol.inequality_multipliers[o.index] = std::max(0.0, y), sol.working_set.inequalities.push_back(o.index);
          break;
        case RowKind::upper_bound:
          sol.upper_bound_multipliers[o.index] = std::max(0.0, y), sol.working_set.upper_bounds.push_back(o.index);
          break;
        case RowKind::lower_bound:
          sol.lower_bound_multipliers[o.index] = std::max(0.0, y), sol.working_set.lower_bounds.push_back(o.index);
          break;
      }
    }
    return sol;
  };

  // Makes row p active (Goldfarb-Idnani step 2): partial steps drop working inequalities whose
  // multiplier reaches 0, full steps move x until row p holds. Returns false with a reason on
  // infeasibility or the iteration limit.
  std::string failure;
  QpStatus failure_status = QpStatus::infeasible;
  auto make_active = [&](int p) {
    const bool equality = rows.origin[static_cast<size_t>(p)].kind == RowKind::equality;
    double slack = rows.b[p] - rows.a.row(p).dot(sol.x);
    const double sign = equality && slack > 0.0 ? -1.0 : 1.0;  // an equality is approached from its violated side
    const VectorXd normal = -sign * rows.a.row(p).transpose();
    double u_p = 0.0;
    for (;;) {
      if (sol.iterations >= options.max_iterations) {
        failure_status = QpStatus::max_iterations, failure = "reached max_iterations";
        return false;
      }
      ++sol.iterations;
      const auto dir = ws.directions(normal);
      // Partial step length: the first working inequality whose multiplier falls to 0.
      double t1 = kInfinity;
      Index blocking = -1;
      for (Index k = 0; k < ws.size(); ++k) {
        if (rows.origin[static_cast<size_t>(ws.row(k))].kind == RowKind::equality || dir.r[k] <= 0.0) continue;
        const double ratio = ws.multipliers()[k] / dir.r[k];
        if (ratio < t1) t1 = ratio, blocking = k;
      }
      // Full step length: row p holds (slack sign * (b - a'x) rises to 0 along z).
      const double t2 = dir.dependent ? kInfinity : std::max(0.0, -sign * slack) / dir.z.dot(normal);
      const double t = std::min(t1, t2);
      if (!std::isfinite(t)) {
        if (equality && std::abs(slack) <= tol) return true;  // redundant equality, already satisfied
        failure = "constraints are inconsistent (" + std::string(equality ? "equality" : "inequality") +
                  " row cannot be satisfied together with the working set)";
        return false;
      }
      if (ws.size()) ws.multipliers() -= t * dir.r;
      u_p += t;
      if (!dir.dependent) sol.x += t * dir.z;
      if (t == t2) {
        ws.add(p, sign, normal, u_p);
        active[static_cast<size_t>(p)] = 1;
        return true;
      }
      active[static_cast<size_t>(ws.row(blocking))] = 0;
      ws.drop(blocking);
      slack = rows.b[p] - rows.a.row(p).dot(sol.x);
    }
  };

  for (Index p = 0; p < m_eq; ++p)
    if (!make_active(static_cast<int>(p))) return finish(failure_status, "equality rows: " + failure);
  for (;;) {
    // The most violated row (scaled by its norm); none: the dual feasible iterate is primal feasible.
    const VectorXd slack = rows.b - rows.a * sol.x;
    Index p = -1;
    double worst = 0.0;
    for (Index k = m_eq; k < m; ++k) {
      if (active[static_cast<size_t>(k)] || slack[k] >= -tol) continue;
      const double scaled = slack[k] / std::max(rows.norms[k], 1e-300);
      if (scaled < worst) worst = scaled, p = k;
    }
    if (p < 0) {
      refine_dual_solution(qp, rows, active, tol, ws, sol.x);
      return finish(QpStatus::optimal, "optimal");
    }
    if (!make_active(static_cast<int>(p))) return finish(failure_status, failure);
  }
}

}  // namespace cyclopt::qp
