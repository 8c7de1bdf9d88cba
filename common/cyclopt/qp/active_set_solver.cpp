#include "cyclopt/qp/active_set_solver.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace cyclopt::qp {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A row is independent of the working set if its component orthogonal to it exceeds this
// fraction of its norm; a constraint blocks a step if a'p exceeds this fraction of |a||p|.
constexpr double kDependenceTolerance = 1e-9;
constexpr double kDirectionTolerance = 1e-12;
// A subspace Newton step below this (relative to max(1, |x|_inf)) is rounding noise.
constexpr double kStationaryStep = 1e-13;
// Ulps of |E| |x| + |e| that E x = e may miss by rounding alone (the consistency check of the start).
constexpr double kEqualityRoundingUlps = 64.0;

// A_in rows, then finite upper bounds (x_i <= u_i), then finite lower bounds (-x_i <= -l_i):
// every inequality-type constraint as one row of C x <= c.
enum class RowKind { inequality, upper_bound, lower_bound };
struct RowOrigin {
  RowKind kind;
  int index;  // row of A_in, or variable index
};

struct StackedInequalities {
  MatrixXd matrix;
  VectorXd rhs;
  std::vector<RowOrigin> origin;
};

StackedInequalities stack_inequalities(const QuadraticProgram& qp) {
  const Index n = qp.num_variables();
  std::vector<RowOrigin> origin;
  for (Index i = 0; i < qp.inequality_matrix.rows(); ++i) origin.push_back({RowKind::inequality, static_cast<int>(i)});
  for (Index i = 0; i < qp.upper_bounds.size(); ++i)
    if (std::isfinite(qp.upper_bounds[i])) origin.push_back({RowKind::upper_bound, static_cast<int>(i)});
  for (Index i = 0; i < qp.lower_bounds.size(); ++i)
    if (std::isfinite(qp.lower_bounds[i])) origin.push_back({RowKind::lower_bound, static_cast<int>(i)});
  StackedInequalities s{MatrixXd::Zero(static_cast<Index>(origin.size()), n), VectorXd(static_cast<Index>(origin.size())), origin};
  for (Index r = 0; r < s.matrix.rows(); ++r) {
    const RowOrigin& o = origin[static_cast<size_t>(r)];
    switch (o.kind) {
      case RowKind::inequality:
        s.matrix.row(r) = qp.inequality_matrix.row(o.index);
        s.rhs[r] = qp.inequality_rhs[o.index];
        break;
      case RowKind::upper_bound:
        s.matrix(r, o.index) = 1.0;
        s.rhs[r] = qp.upper_bounds[o.index];
        break;
      case RowKind::lower_bound:
        s.matrix(r, o.index) = -1.0;
        s.rhs[r] = -qp.lower_bounds[o.index];
        break;
    }
  }
  return s;
}

// Orthonormal basis of the span of accepted rows (twice-iterated Gram-Schmidt), to keep a
// working set linearly independent.
class RowSpan {
 public:
  bool try_add(const VectorXd& row) {
    const double norm = row.norm();
    if (norm == 0.0) return false;
    VectorXd r = row;
    for (int pass = 0; pass < 2; ++pass)
      for (const VectorXd& q : basis_) r -= q.dot(r) * q;
    const double residual = r.norm();
    if (residual <= kDependenceTolerance * norm) return false;
    basis_.push_back(r / residual);
    return true;
  }

 private:
  std::vector<VectorXd> basis_;
};

// The constraints of one active-set run: E x = e (rows eq_rows are held), C x <= c.
struct LinearConstraints {
  const MatrixXd& E;
  const VectorXd& e;
  const MatrixXd& C;
  const VectorXd& c;
};

// QR of the working-set matrix' A_W' = [Q1 Q2] [R; 0]: Q2 spans the null space of A_W. Q is kept
// as Householder reflectors and applied only to what is needed (forming it would cost O(n^2 w)).
struct WorkingFactorization {
  Eigen::HouseholderQR<MatrixXd> qr;
  Index n = 0;
  Index w = 0;

  explicit WorkingFactorization(const MatrixXd& working_transposed)
      : n(working_transposed.rows()), w(working_transposed.cols()) {
    if (w > 0) qr.compute(working_transposed);
  }
  MatrixXd null_space() const {
    MatrixXd Z = MatrixXd::Identity(n, n).rightCols(n - w);
    if (w > 0) Z.applyOnTheLeft(qr.householderQ());
    return Z;
  }
  auto R() const { return qr.matrixQR().topLeftCorner(w, w).triangularView<Eigen::Upper>(); }
  // Multipliers y with A_W' y = -grad (exact when grad is in the range of A_W').
  VectorXd multipliers(const VectorXd& grad) const {
    if (w == 0) return VectorXd();
    const VectorXd qt_grad = qr.householderQ().transpose() * grad;
    return R().solve(-qt_grad.head(w));
  }
  // Minimum-norm x with A_W x = b: x = Q1 R^-T b.
  VectorXd particular_solution(const VectorXd& b) const {
    VectorXd x = VectorXd::Zero(n);
    if (w == 0) return x;
    x.head(w) = qr.matrixQR().topLeftCorner(w, w).transpose().triangularView<Eigen::Lower>().solve(b);
    return qr.householderQ() * x;
  }
};

struct SubspaceStep {
  VectorXd p;
  bool ray = false;  // zero-curvature descent direction: no natural step length
};

// Variables with a nonzero Hessian column (the others - e.g. the slacks of (6.13) - have no curvature).
std::vector<int> curved_variables(const MatrixXd& H) {
  std::vector<int> curved;
  for (Index j = 0; j < H.cols(); ++j)
    if (H.col(j).cwiseAbs().maxCoeff() > 0.0) curved.push_back(static_cast<int>(j));
  return curved;
}

// Minimises the quadratic model over x + null(A_W), in the coordinates of the free variables
// (columns of Z): Newton step on the positive-curvature part of the reduced Hessian Z'HZ; if the
// reduced gradient has a component of zero curvature, that component (negated) is a descent ray
// instead. Z'HZ is never formed: with H_SS = V L V' on the curved free variables S,
// Z'HZ = B'B for B = L^1/2 V' Z_S, and the thin SVD of B' (rank <= |S|) gives its eigen-pairs, so
// many zero-curvature variables cost only O(k |S|^2).
SubspaceStep subspace_step(const MatrixXd& H, const std::vector<int>& free_variables, const std::vector<char>& is_curved,
                           const VectorXd& grad_free, const MatrixXd& Z, double curvature_threshold, double gradient_threshold) {
  SubspaceStep step{VectorXd::Zero(grad_free.size()), false};
  if (Z.cols() == 0) return step;
  std::vector<int> curved, positions;  // variable indices and their rows in Z
  for (size_t k = 0; k < free_variables.size(); ++k)
    if (is_curved[static_cast<size_t>(free_variables[k])]) curved.push_back(free_variables[k]), positions.push_back(static_cast<int>(k));
  const VectorXd gz = Z.transpose() * grad_free;
  VectorXd newton = VectorXd::Zero(Z.cols());
  VectorXd flat = gz;
  if (!curved.empty()) {
    const Eigen::SelfAdjointEigenSolver<MatrixXd> h(H(curved, curved));
    std::vector<Index> positive;
    for (Index j = 0; j < h.eigenvalues().size(); ++j)
      if (h.eigenvalues()[j] > curvature_threshold) positive.push_back(j);
    if (!positive.empty()) {
      MatrixXd Bt(Z.cols(), static_cast<Index>(positive.size()));  // B' = Z_S' V L^1/2
      const MatrixXd ZS = Z(positions, Eigen::all);
      for (size_t j = 0; j < positive.size(); ++j)
        Bt.col(static_cast<Index>(j)) = std::sqrt(h.eigenvalues()[positive[j]]) * (ZS.transpose() * h.eigenvectors().col(positive[j]));
      const Eigen::JacobiSVD<MatrixXd> svd(Bt, Eigen::ComputeThinU);
      for (Index j = 0; j < svd.singularValues().size(); ++j) {
        const double curvature = svd.singularValues()[j] * svd.singularValues()[j];
        if (curvature <= curvature_threshold) continue;
        const double coefficient = svd.matrixU().col(j).dot(gz);
        newton -= (coefficient / curvature) * svd.matrixU().col(j);
        flat -= coefficient * svd.matrixU().col(j);
      }
    }
  }
  if (flat.norm() > gradient_threshold) {
    step.p = -Z * flat;
    step.ray = true;
  } else {
    step.p = Z * newton;
  }
  return step;
}

// Rows of C that are simple bounds (one nonzero, +-1): the variable they bound, else -1.
std::vector<int> simple_bound_variables(const MatrixXd& C) {
  std::vector<int> variable(static_cast<size_t>(C.rows()), -1);
  for (Index r = 0; r < C.rows(); ++r) {
    Index nonzeros = 0, j = -1;
    for (Index k = 0; k < C.cols(); ++k)
      if (C(r, k) != 0.0) ++nonzeros, j = k;
    if (nonzeros == 1 && std::abs(C(r, j)) == 1.0) variable[static_cast<size_t>(r)] = static_cast<int>(j);
  }
  return variable;
}

// The working set seen as fixed variables (its simple-bound rows) and general rows on the free
// variables: the null-space factorisation then only has the free variables' dimension, which keeps
// the l1 subproblems (6.13)/(6.14) - many slacks, most at their bound 0 - cheap.
struct Subspace {
  std::vector<int> free_variables;
  std::vector<int> general;  // positions in `working` of general rows
  std::optional<WorkingFactorization> factorization;  // of [E rows; general rows]' on the free variables
};

Subspace make_subspace(const LinearConstraints& lc, const std::vector<int>& bound_variable, const std::vector<int>& eq_rows,
                       const std::vector<int>& working) {
  const Index n = lc.C.cols() ? lc.C.cols() : lc.E.cols();
  Subspace s;
  std::vector<char> fixed(static_cast<size_t>(n), 0);
  for (size_t k = 0; k < working.size(); ++k) {
    const int j = bound_variable[static_cast<size_t>(working[k])];
    if (j >= 0)
      fixed[static_cast<size_t>(j)] = 1;
    else
      s.general.push_back(static_cast<int>(k));
  }
  for (Index j = 0; j < n; ++j)
    if (!fixed[static_cast<size_t>(j)]) s.free_variables.push_back(static_cast<int>(j));
  MatrixXd at(static_cast<Index>(s.free_variables.size()), static_cast<Index>(eq_rows.size() + s.general.size()));
  Index col = 0;
  for (int r : eq_rows) at.col(col++) = lc.E(r, s.free_variables).transpose();
  for (int k : s.general) at.col(col++) = lc.C(working[static_cast<size_t>(k)], s.free_variables).transpose();
  s.factorization.emplace(at);
  return s;
}

struct RunOutcome {
  QpStatus status = QpStatus::max_iterations;
  int iterations = 0;
  VectorXd eq_multipliers;  // per E row
  VectorXd in_multipliers;  // per C row
};

// Primal active-set iteration from a feasible x with independent working set. Stops early
// (status optimal, no multipliers) once the objective falls to stop_objective (phase 1).
RunOutcome run_active_set(const MatrixXd& H, const VectorXd& g, const LinearConstraints& lc, const std::vector<int>& eq_rows,
                          std::vector<int>& working, VectorXd& x, const ActiveSetOptions& options, int max_iterations,
                          double stop_objective) {
  const Index n = x.size();
  const double curvature_threshold = options.curvature_tolerance * std::max(1.0, H.size() ? H.cwiseAbs().maxCoeff() : 0.0);
  const VectorXd row_norms = lc.C.rowwise().norm();
  const std::vector<int> bound_variable = simple_bound_variables(lc.C);
  std::vector<char> is_curved(static_cast<size_t>(n), 0);
  for (int j : curved_variables(H)) is_curved[static_cast<size_t>(j)] = 1;
  std::vector<char> in_working(static_cast<size_t>(lc.C.rows()), 0);
  for (int r : working) in_working[static_cast<size_t>(r)] = 1;
  RunOutcome out;
  bool at_subspace_minimum = false;
  bool degenerate = false;  // the last step had zero length
  for (;; ++out.iterations) {
    if (out.iterations >= max_iterations) return out;
    const Subspace sub = make_subspace(lc, bound_variable, eq_rows, working);
    const WorkingFactorization& factorization = *sub.factorization;
    const VectorXd grad = H * x + g;
    const VectorXd grad_free = grad(sub.free_variables);
    SubspaceStep step{VectorXd::Zero(n), false};
    if (!at_subspace_minimum) {
      const SubspaceStep free_step =
          subspace_step(H, sub.free_variables, is_curved, grad_free, factorization.null_space(), curvature_threshold,
                        options.optimality_tolerance * std::max(1.0, grad.lpNorm<Eigen::Infinity>()));
      step.p(sub.free_variables) = free_step.p;
      step.ray = free_step.ray;
    }
    const bool stationary =
        !step.ray && step.p.lpNorm<Eigen::Infinity>() <= kStationaryStep * std::max(1.0, x.lpNorm<Eigen::Infinity>());
    if (stationary) {
      // Multipliers of equality and general rows from the free variables; of a bound row on x_j
      // from component j of grad + A' y = 0.
      const VectorXd y_rows = factorization.multipliers(grad_free);
      const Index w_eq = static_cast<Index>(eq_rows.size());
      VectorXd residual = grad;
      for (Index k = 0; k < w_eq; ++k) residual += y_rows[k] * lc.E.row(eq_rows[static_cast<size_t>(k)]).transpose();
      VectorXd y_working = VectorXd::Zero(static_cast<Index>(working.size()));
      for (size_t k = 0; k < sub.general.size(); ++k) {
        const int position = sub.general[k];
        y_working[position] = y_rows[w_eq + static_cast<Index>(k)];
        residual += y_working[position] * lc.C.row(working[static_cast<size_t>(position)]).transpose();
      }
      for (Index k = 0; k < y_working.size(); ++k) {
        const int r = working[static_cast<size_t>(k)], j = bound_variable[static_cast<size_t>(r)];
        if (j >= 0) y_working[k] = -residual[j] / lc.C(r, j);
      }
      double largest = 0.0;
      if (y_rows.size()) largest = y_rows.cwiseAbs().maxCoeff();
      if (y_working.size()) largest = std::max(largest, y_working.cwiseAbs().maxCoeff());
      // Drop the most negative multiplier; after a zero-length step (degenerate vertex) drop the
      // lowest-numbered row with a negative one instead (Bland's rule), which cannot cycle.
      const double threshold = -options.optimality_tolerance * std::max(1.0, largest);
      double most_negative = threshold;
      Index worst = -1;
      for (Index k = 0; k < y_working.size(); ++k) {
        if (y_working[k] >= threshold) continue;
        if (degenerate ? (worst < 0 || working[static_cast<size_t>(k)] < working[static_cast<size_t>(worst)])
                       : y_working[k] < most_negative)
          most_negative = y_working[k], worst = k;
      }
      if (worst < 0) {
        out.status = QpStatus::optimal;
        out.eq_multipliers = VectorXd::Zero(lc.E.rows());
        out.in_multipliers = VectorXd::Zero(lc.C.rows());
        for (Index k = 0; k < w_eq; ++k) out.eq_multipliers[eq_rows[static_cast<size_t>(k)]] = y_rows[k];
        for (Index k = 0; k < y_working.size(); ++k) out.in_multipliers[working[static_cast<size_t>(k)]] = std::max(0.0, y_working[k]);
        return out;
      }
      const auto dropped = working.begin() + worst;
      in_working[static_cast<size_t>(*dropped)] = 0;
      working.erase(dropped);
      at_subspace_minimum = false;
      continue;
    }
    // Ratio test; ties go to the lowest row index (Bland-like, against cycling).
    double alpha = step.ray ? kInfinity : 1.0;
    Index blocking = -1;
    const double p_norm = step.p.norm();
    const VectorXd Cp = lc.C * step.p;
    for (Index i = 0; i < lc.C.rows(); ++i) {
      if (in_working[static_cast<size_t>(i)] || Cp[i] <= kDirectionTolerance * row_norms[i] * p_norm) continue;
      const double ratio = std::max(0.0, lc.c[i] - lc.C.row(i).dot(x)) / Cp[i];
      if (ratio < alpha) alpha = ratio, blocking = i;
    }
    if (blocking < 0 && step.ray) {
      out.status = QpStatus::unbounded;
      return out;
    }
    x += alpha * step.p;
    degenerate = blocking >= 0 && alpha * p_norm <= kStationaryStep * std::max(1.0, x.lpNorm<Eigen::Infinity>());
    at_subspace_minimum = blocking < 0;
    if (blocking >= 0) {
      working.push_back(static_cast<int>(blocking));
      in_working[static_cast<size_t>(blocking)] = 1;
    }
    if (g.dot(x) + 0.5 * x.dot(H * x) <= stop_objective) {
      out.status = QpStatus::optimal;
      ++out.iterations;
      return out;
    }
  }
}

// The rows of `candidates` active at x (all of them if x is null) that, with the equality rows,
// stay linearly independent: bound rows fixing distinct variables, then general rows independent
// of the equalities on the remaining free variables. (If a fixing makes the equalities dependent,
// bound rows are treated like general rows instead - rare, and slower.)
std::vector<int> independent_rows(const std::vector<int>& candidates, const LinearConstraints& lc,
                                  const std::vector<int>& bound_variable, const std::vector<int>& eq_rows, const VectorXd* x,
                                  double tolerance) {
  const Index n = lc.C.cols();
  std::vector<int> active;
  for (int r : candidates)
    if (x == nullptr || std::abs(lc.C.row(r).dot(*x) - lc.c[r]) <= tolerance) active.push_back(r);
  for (bool fix_bounds : {true, false}) {
    std::vector<char> fixed(static_cast<size_t>(n), 0);
    std::vector<int> kept;
    if (fix_bounds)
      for (int r : active) {
        const int j = bound_variable[static_cast<size_t>(r)];
        if (j >= 0 && !fixed[static_cast<size_t>(j)]) fixed[static_cast<size_t>(j)] = 1, kept.push_back(r);
      }
    std::vector<int> free_variables;
    for (Index j = 0; j < n; ++j)
      if (!fixed[static_cast<size_t>(j)]) free_variables.push_back(static_cast<int>(j));
    RowSpan span;
    bool equalities_independent = true;
    for (int r : eq_rows) equalities_independent = span.try_add(lc.E(r, free_variables).transpose()) && equalities_independent;
    if (!equalities_independent) continue;
    for (int r : active)
      if ((!fix_bounds || bound_variable[static_cast<size_t>(r)] < 0) && span.try_add(lc.C(r, free_variables).transpose()))
        kept.push_back(r);
    return kept;
  }
  return {};
}

void validate(const ActiveSetOptions& o) {
  if (o.max_iterations < 1) throw std::invalid_argument("ActiveSetOptions.max_iterations: must be >= 1");
  if (!(o.feasibility_tolerance > 0)) throw std::invalid_argument("ActiveSetOptions.feasibility_tolerance: must be > 0");
  if (!(o.optimality_tolerance > 0)) throw std::invalid_argument("ActiveSetOptions.optimality_tolerance: must be > 0");
  if (!(o.curvature_tolerance > 0)) throw std::invalid_argument("ActiveSetOptions.curvature_tolerance: must be > 0");
}

std::vector<int> stacked_rows(const WorkingSet& ws, const StackedInequalities& s, Index n, Index m_in) {
  auto check = [](int i, Index size, const char* field) {
    if (i < 0 || i >= size)
      throw std::invalid_argument(std::string("WorkingSet.") + field + ": index " + std::to_string(i) + " outside [0, " +
                                  std::to_string(size) + ")");
  };
  std::vector<int> rows;
  for (Index r = 0; r < static_cast<Index>(s.origin.size()); ++r) {
    const RowOrigin& o = s.origin[static_cast<size_t>(r)];
    const std::vector<int>& list = o.kind == RowKind::inequality    ? ws.inequalities
                                   : o.kind == RowKind::upper_bound ? ws.upper_bounds
                                                                    : ws.lower_bounds;
    if (std::find(list.begin(), list.end(), o.index) != list.end()) rows.push_back(static_cast<int>(r));
  }
  for (int i : ws.inequalities) check(i, m_in, "inequalities");
  for (int i : ws.lower_bounds) check(i, n, "lower_bounds");
  for (int i : ws.upper_bounds) check(i, n, "upper_bounds");
  return rows;
}

}  // namespace

const char* to_string(QpStatus status) {
  switch (status) {
    case QpStatus::optimal: return "optimal";
    case QpStatus::infeasible: return "infeasible";
    case QpStatus::unbounded: return "unbounded";
    case QpStatus::max_iterations: return "max_iterations";
  }
  return "unknown";
}

QpSolution solve_active_set(const QuadraticProgram& qp, const ActiveSetOptions& options, const WorkingSet& warm_start) {
  validate(qp);
  validate(options);
  const Index n = qp.num_variables();
  const Index m_eq = qp.equality_matrix.rows();
  const Index m_in = qp.inequality_matrix.rows();
  const StackedInequalities stacked = stack_inequalities(qp);
  const MatrixXd E = m_eq ? qp.equality_matrix : MatrixXd(0, n);
  const LinearConstraints lc{E, qp.equality_rhs, stacked.matrix, stacked.rhs};
  const double tol = options.feasibility_tolerance;

  QpSolution sol;
  sol.equality_multipliers = VectorXd::Zero(m_eq);
  sol.inequality_multipliers = VectorXd::Zero(m_in);
  sol.lower_bound_multipliers = VectorXd::Zero(n);
  sol.upper_bound_multipliers = VectorXd::Zero(n);

  // Independent equality rows; redundant ones are checked for consistency below.
  RowSpan equality_span;
  std::vector<int> eq_rows;
  for (Index i = 0; i < m_eq; ++i)
    if (equality_span.try_add(E.row(i).transpose())) eq_rows.push_back(static_cast<int>(i));

  // Start: the subspace minimiser on the warm-start working set (or on the equalities alone),
  // from the origin clamped into the bounds; warm bound rows fix their variables at the bound.
  const std::vector<int> bound_variable = simple_bound_variables(stacked.matrix);
  const double curvature = options.curvature_tolerance * std::max(1.0, qp.hessian.size() ? qp.hessian.cwiseAbs().maxCoeff() : 0.0);
  VectorXd x = VectorXd::Zero(n);
  if (qp.lower_bounds.size()) x = x.cwiseMax(qp.lower_bounds);
  if (qp.upper_bounds.size()) x = x.cwiseMin(qp.upper_bounds);
  const std::vector<int> warm_rows =
      independent_rows(stacked_rows(warm_start, stacked, n, m_in), lc, bound_variable, eq_rows, nullptr, tol);
  {
    const Subspace sub = make_subspace(lc, bound_variable, eq_rows, warm_rows);
    for (int r : warm_rows) {
      const int j = bound_variable[static_cast<size_t>(r)];
      if (j >= 0) x[j] = stacked.rhs[r] / stacked.matrix(r, j);
    }
    VectorXd rhs(sub.factorization->w);
    Index k = 0;
    for (int r : eq_rows) rhs[k++] = qp.equality_rhs[r] - E.row(r).dot(x);
    for (int position : sub.general) {
      const int r = warm_rows[static_cast<size_t>(position)];
      rhs[k++] = stacked.rhs[r] - stacked.matrix.row(r).dot(x);
    }
    x(sub.free_variables) += sub.factorization->particular_solution(rhs);
    if (!warm_rows.empty()) {
      const VectorXd grad = qp.hessian * x + qp.gradient;
      std::vector<char> is_curved(static_cast<size_t>(n), 0);
      for (int j : curved_variables(qp.hessian)) is_curved[static_cast<size_t>(j)] = 1;
      x(sub.free_variables) += subspace_step(qp.hessian, sub.free_variables, is_curved, grad(sub.free_variables),
                                             sub.factorization->null_space(), curvature, kInfinity)
                                   .p;
    }
  }
  // Redundant equality rows must agree to the tolerance, or to the rounding of E x where the warm
  // start's subspace step is long (from an ill-conditioned Hessian: |x| ~ 1e6 in the walker's
  // elastic subproblems, where E x rounds at ~1e-7 with consistent rows).
  const double equality_residual = m_eq ? (E * x - qp.equality_rhs).lpNorm<Eigen::Infinity>() : 0.0;
  if (equality_residual > tol &&
      equality_residual > kEqualityRoundingUlps * std::numeric_limits<double>::epsilon() *
                              (E.cwiseAbs().rowwise().sum().maxCoeff() * x.lpNorm<Eigen::Infinity>() +
                               qp.equality_rhs.lpNorm<Eigen::Infinity>())) {
    sol.status = QpStatus::infeasible;
    sol.message = "equality constraints are inconsistent (redundant rows contradict each other)";
    sol.x = x;
    return sol;
  }

  std::vector<int> working;
  const Index m_c = stacked.matrix.rows();
  const VectorXd residuals = stacked.matrix * x - stacked.rhs;
  const double violation = m_c ? std::max(0.0, residuals.maxCoeff()) : 0.0;
  if (violation <= tol) {
    working = independent_rows(warm_rows, lc, bound_variable, eq_rows, &x, tol);
  } else {
    // Phase 1: min t over (x, t) s.t. E x = e, C_i x - t <= c_i for the general rows and the
    // violated bound rows, the satisfied bound rows kept hard (so warm bound rows stay fixed),
    // t >= 0, from (x, violation).
    MatrixXd E1 = MatrixXd::Zero(m_eq, n + 1);
    E1.leftCols(n) = E;
    MatrixXd C1 = MatrixXd::Zero(m_c + 1, n + 1);
    C1.topLeftCorner(m_c, n) = stacked.matrix;
    for (Index r = 0; r < m_c; ++r)
      if (bound_variable[static_cast<size_t>(r)] < 0 || residuals[r] > 0.0) C1(r, n) = -1.0;
    C1(m_c, n) = -1.0;
    VectorXd c1 = VectorXd::Zero(m_c + 1);
    c1.head(m_c) = stacked.rhs;
    VectorXd g1 = VectorXd::Zero(n + 1);
    g1[n] = 1.0;
    VectorXd x1(n + 1);
    x1 << x, violation;
    const LinearConstraints lc1{E1, qp.equality_rhs, C1, c1};
    std::vector<int> working1 = independent_rows(warm_rows, lc1, simple_bound_variables(C1), eq_rows, &x1, tol);
    const RunOutcome phase1 =
        run_active_set(MatrixXd::Zero(n + 1, n + 1), g1, lc1, eq_rows, working1, x1, options, options.max_iterations, tol);
    sol.phase_one_iterations = sol.iterations = phase1.iterations;
    x = x1.head(n);
    if (phase1.status == QpStatus::max_iterations) {
      sol.status = QpStatus::max_iterations;
      sol.message = "phase 1 (feasibility) reached max_iterations";
      sol.x = x;
      return sol;
    }
    if (x1[n] > tol) {
      sol.status = QpStatus::infeasible;
      sol.message = "constraints are inconsistent: least achievable max violation " + std::to_string(x1[n]);
      sol.x = x;
      return sol;
    }
    std::vector<int> candidates;
    for (int r : working1)
      if (r < m_c) candidates.push_back(r);
    working = independent_rows(candidates, lc, bound_variable, eq_rows, &x, tol);
  }

  const RunOutcome phase2 = run_active_set(qp.hessian, qp.gradient, lc, eq_rows, working, x, options,
                                           options.max_iterations - sol.iterations, -kInfinity);
  sol.iterations += phase2.iterations;
  sol.status = phase2.status;
  sol.x = x;
  sol.objective = qp.objective(x);
  switch (phase2.status) {
    case QpStatus::optimal: sol.message = "optimal"; break;
    case QpStatus::unbounded: sol.message = "objective decreases without bound along a feasible zero-curvature ray"; break;
    default: sol.message = "reached max_iterations"; break;
  }
  for (int r : working) {
    const RowOrigin& o = stacked.origin[static_cast<size_t>(r)];
    (o.kind == RowKind::inequality    ? sol.working_set.inequalities
     : o.kind == RowKind::upper_bound ? sol.working_set.upper_bounds
                                      : sol.working_set.lower_bounds)
        .push_back(o.index);
  }
  if (phase2.status != QpStatus::optimal) return sol;
  sol.equality_multipliers = phase2.eq_multipliers;
  for (Index r = 0; r < stacked.matrix.rows(); ++r) {
    const RowOrigin& o = stacked.origin[static_cast<size_t>(r)];
    const double y = phase2.in_multipliers[r];
    switch (o.kind) {
      case RowKind::inequality: sol.inequality_multipliers[o.index] = y; break;
      case RowKind::upper_bound: sol.upper_bound_multipliers[o.index] = y; break;
      case RowKind::lower_bound: sol.lower_bound_multipliers[o.index] = y; break;
    }
  }
  return sol;
}

}  // namespace cyclopt::qp
