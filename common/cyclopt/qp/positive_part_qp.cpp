#include "cyclopt/qp/positive_part_qp.hpp"

#include "cyclopt/qp/dual_active_set_solver.hpp"
#include "cyclopt/qp/working_set_refinement.hpp"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
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

constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Kind { term, inequality, upper_bound, lower_bound, equality };
enum class State { lower, upper, free };

// Every dual variable: its row of M, right-hand side and box.
struct DualRows {
  MatrixXd M;
  VectorXd r, lo, hi;
  std::vector<Kind> kind;
  std::vector<int> index;  // term, row of A_in / A_eq, or variable
};

DualRows dual_rows(const QuadraticProgram& qp, const PositivePartTerms& terms) {
  const Index n = qp.num_variables(), K = terms.rhs.size();
  std::vector<std::pair<Kind, int>> rows;
  for (Index k = 0; k < K; ++k) rows.emplace_back(Kind::term, static_cast<int>(k));
  for (Index i = 0; i < qp.inequality_rhs.size(); ++i) rows.emplace_back(Kind::inequality, static_cast<int>(i));
  for (Index j = 0; j < qp.upper_bounds.size(); ++j)
    if (std::isfinite(qp.upper_bounds[j])) rows.emplace_back(Kind::upper_bound, static_cast<int>(j));
  for (Index j = 0; j < qp.lower_bounds.size(); ++j)
    if (std::isfinite(qp.lower_bounds[j])) rows.emplace_back(Kind::lower_bound, static_cast<int>(j));
  for (Index i = 0; i < qp.equality_rhs.size(); ++i) rows.emplace_back(Kind::equality, static_cast<int>(i));
  const Index N = static_cast<Index>(rows.size());
  DualRows d{MatrixXd::Zero(N, n), VectorXd(N), VectorXd::Zero(N), VectorXd::Constant(N, kInf), {}, {}};
  for (Index j = 0; j < N; ++j) {
    const auto [kind, i] = rows[static_cast<size_t>(j)];
    d.kind.push_back(kind);
    d.index.push_back(i);
    switch (kind) {
      case Kind::term:
        d.M.row(j) = terms.matrix.row(i);
        d.r[j] = terms.rhs[i];
        d.hi[j] = terms.weights[i];
        break;
      case Kind::inequality:
        d.M.row(j) = qp.inequality_matrix.row(i);
        d.r[j] = qp.inequality_rhs[i];
        break;
      case Kind::upper_bound:
        d.M(j, i) = 1.0;
        d.r[j] = qp.upper_bounds[i];
        break;
      case Kind::lower_bound:
        d.M(j, i) = -1.0;
        d.r[j] = -qp.lower_bounds[i];
        break;
      case Kind::equality:
        d.M.row(j) = qp.equality_matrix.row(i);
        d.r[j] = qp.equality_rhs[i];
        d.lo[j] = -kInf;
        break;
    }
  }
  return d;
}

// The free set's move: towards its stationary point (ray = false) or, where the free rows are
// inconsistent, along a direction of no curvature that decreases the dual (ray = true).
struct FreeStep {
  VectorXd direction;
  bool ray = false;
};

// Stationary point of 1/2 |h + G u|^2 + r'u over u (G = L^-1 M_F'): G'G u = -(G'h + r).
FreeStep free_step(const MatrixXd& G, const VectorXd& h, const VectorXd& r, const VectorXd& u0) {
  const Index f = G.cols();
  const VectorXd rhs = G.transpose() * h + r;
  Eigen::ColPivHouseholderQR<MatrixXd> qr(G);
  if (qr.rank() == f) {  // G = Q R P': u = -P R^-1 R^-T P' rhs
    const auto R = qr.matrixR().topLeftCorner(f, f).triangularView<Eigen::Upper>();
    VectorXd z = qr.colsPermutation().transpose() * rhs;
    R.transpose().solveInPlace(z);
    R.solveInPlace(z);
    return {-(qr.colsPermutation() * z) - u0, false};
  }
  // Dependent free rows: their null space N; a right-hand side with a component there makes the
  // dual unbounded along -that component, else the minimum-norm stationary point.
  const Eigen::JacobiSVD<MatrixXd> svd(G, Eigen::ComputeFullV);
  const VectorXd& s = svd.singularValues();
  const double cutoff = s.size() ? s[0] * 1e-10 : 0.0;
  Index k = 0;
  while (k < s.size() && s[k] > cutoff) ++k;
  const MatrixXd V = svd.matrixV();
  const VectorXd r_null = r - V.leftCols(k) * (V.leftCols(k).transpose() * r);
  if (r_null.norm() > 1e-9 * std::max(1.0, r.norm())) return {-r_null, true};
  const VectorXd c = V.leftCols(k).transpose() * rhs;
  return {-(V.leftCols(k) * c.cwiseQuotient(s.head(k).cwiseAbs2())) - u0, false};
}

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("solve_positive_part_qp: " + message);
}

}  // namespace

PositivePartQpSolution solve_positive_part_qp(const QuadraticProgram& qp, const PositivePartTerms& terms,
                                              const ActiveSetOptions& options, const PositivePartQpStart& start) {
  validate(qp);
  const Index n = qp.num_variables(), K = terms.rhs.size();
  require(terms.matrix.rows() == K && terms.matrix.cols() == n, "terms.matrix must be terms.rhs.size() x n");
  require(terms.weights.size() == K, "terms.weights needs one entry per term");
  require(K == 0 || terms.weights.minCoeff() > 0.0, "terms.weights must be > 0");
  require(is_strictly_convex(qp.hessian, options.curvature_tolerance), "the Hessian must be positive definite");
  require(start.sigma.size() == 0 || start.sigma.size() == K, "start.sigma needs one entry per term or none");
  const Eigen::LLT<MatrixXd> llt(qp.hessian);
  const auto L = llt.matrixL();
  const DualRows rows = dual_rows(qp, terms);
  const Index N = rows.r.size();
  const VectorXd row_scale = rows.M.rowwise().norm().cwiseMax(1.0);

  PositivePartQpSolution out;
  QpSolution& sol = out.qp;
  VectorXd v = VectorXd::Zero(N);
  std::vector<State> state(static_cast<size_t>(N), State::lower);
  std::vector<int> free;
  const auto listed = [](const std::vector<int>& list, int i) { return std::find(list.begin(), list.end(), i) != list.end(); };
  for (Index j = 0; j < N; ++j) {
    const size_t k = static_cast<size_t>(j);
    const int i = rows.index[k];
    bool is_free = false;
    switch (rows.kind[k]) {
      case Kind::equality: is_free = true; break;
      case Kind::inequality: is_free = listed(start.active.inequalities, i); break;
      case Kind::upper_bound: is_free = listed(start.active.upper_bounds, i); break;
      case Kind::lower_bound: is_free = listed(start.active.lower_bounds, i); break;
      case Kind::term:
        if (start.sigma.size()) {
          v[j] = std::clamp(start.sigma[i], 0.0, rows.hi[j]);
          if (v[j] == rows.hi[j]) state[k] = State::upper;
          is_free = v[j] > 0.0 && v[j] < rows.hi[j];
        }
        break;
    }
    if (is_free) state[k] = State::free, free.push_back(static_cast<int>(j));
  }
  MatrixXd Ghat(n, N);  // L^-1 M_j', column j computed when j is first free
  std::vector<char> has_column(static_cast<size_t>(N), 0);
  auto column = [&](int j) {
    if (!has_column[static_cast<size_t>(j)]) {
      Ghat.col(j) = L.solve(rows.M.row(j).transpose());
      has_column[static_cast<size_t>(j)] = 1;
    }
  };
  // The start's free set is kept linearly independent in the metric of H^-1 (equalities first):
  // a dependent free variable starts at its nearest bound instead. (A free set's stationary point
  // spreads multipliers over dependent rows; started from such a point, the free set would carry
  // every row of a held joint.)
  {
    std::vector<Eigen::VectorXd> basis;
    std::vector<int> kept;
    for (int j : free) {
      column(j);
      Eigen::VectorXd q = Ghat.col(j);
      const double norm = q.norm();
      for (int pass = 0; pass < 2; ++pass)
        for (const Eigen::VectorXd& b : basis) q -= b.dot(q) * b;
      if (q.norm() > 1e-9 * norm || rows.kind[static_cast<size_t>(j)] == Kind::equality) {
        if (q.norm() > 0.0) basis.push_back(q / q.norm());
        kept.push_back(j);
        continue;
      }
      const bool to_lower = std::abs(v[j] - rows.lo[j]) <= std::abs(v[j] - rows.hi[j]);
      state[static_cast<size_t>(j)] = to_lower ? State::lower : State::upper;
      v[j] = to_lower ? rows.lo[j] : rows.hi[j];
    }
    free = std::move(kept);
  }
  auto at_bound_sum = [&]() {  // g + sum of M_j' v_j over the variables not free
    VectorXd s = qp.gradient;
    for (Index j = 0; j < N; ++j)
      if (state[static_cast<size_t>(j)] != State::free && v[j] != 0.0) s += v[j] * rows.M.row(j).transpose();
    return s;
  };
  std::vector<char> excluded(static_cast<size_t>(N), 0);
  int entering = -1;
  VectorXd x(n);
  for (;;) {
    // Inner loop: the free set's stationary point, as far as the box allows.
    while (!free.empty()) {
      if (sol.iterations >= options.max_iterations) break;
      for (int j : free) column(j);
      const MatrixXd G = Ghat(Eigen::all, free);
      const VectorXd h = L.solve(at_bound_sum());
      const VectorXd u0 = v(free);
      const FreeStep step = free_step(G, h, rows.r(free), u0);
      double alpha = step.ray ? kInf : 1.0;
      int limiting = -1;
      for (size_t k = 0; k < free.size(); ++k) {
        const int j = free[k];
        const double dj = step.direction[static_cast<Index>(k)];
        if (dj < 0.0 && std::isfinite(rows.lo[j])) {
          const double a = (rows.lo[j] - v[j]) / dj;
          if (a < alpha) alpha = a, limiting = j;
        } else if (dj > 0.0 && std::isfinite(rows.hi[j])) {
          const double a = (rows.hi[j] - v[j]) / dj;
          if (a < alpha) alpha = a, limiting = j;
        }
      }
      if (!std::isfinite(alpha)) {
        sol.status = QpStatus::infeasible;
        sol.message = "the constraints are inconsistent (the dual decreases without bound)";
        sol.x = -llt.solve(at_bound_sum() + rows.M(free, Eigen::all).transpose() * v(free));
        out.sigma = v.head(K);
        return out;
      }
      alpha = std::max(0.0, alpha);
      for (size_t k = 0; k < free.size(); ++k) v[free[k]] += alpha * step.direction[static_cast<Index>(k)];
      if (!step.ray && alpha >= 1.0) break;
      // The limiting variable, and any other that reached its bound by rounding, leave the free set.
      std::vector<int> still_free;
      for (int j : free) {
        const size_t k = static_cast<size_t>(j);
        const double gap = 1e-14 * std::max(1.0, std::abs(v[j]));
        if (j == limiting || v[j] <= rows.lo[j] + gap || v[j] >= rows.hi[j] - gap) {
          const bool to_lower = std::isfinite(rows.lo[j]) && std::abs(v[j] - rows.lo[j]) <= std::abs(v[j] - rows.hi[j]);
          state[k] = to_lower ? State::lower : State::upper;
          v[j] = to_lower ? rows.lo[j] : rows.hi[j];
        } else {
          still_free.push_back(j);
        }
      }
      if (alpha == 0.0 && entering >= 0 && state[static_cast<size_t>(entering)] != State::free)
        excluded[static_cast<size_t>(entering)] = 1;  // entered and left without moving: degenerate
      else if (alpha > 0.0)
        std::fill(excluded.begin(), excluded.end(), 0);
      free = std::move(still_free);
      ++sol.iterations;
    }
    // Outer step: the primal point of v, and the variable whose row most violates its bound's
    // condition (a row violated at its lower bound, a negative piece at sigma = w) enters.
    x = -llt.solve(at_bound_sum() + (free.empty() ? VectorXd::Zero(n) : VectorXd(rows.M(free, Eigen::all).transpose() * v(free))));
    const VectorXd residual = rows.M * x - rows.r;
    entering = -1;
    double worst = options.feasibility_tolerance;
    for (Index j = 0; j < N; ++j) {
      const size_t k = static_cast<size_t>(j);
      if (state[k] == State::free || excluded[k]) continue;
      const double violation = (state[k] == State::lower ? residual[j] : -residual[j]) / row_scale[j];
      if (violation > worst) worst = violation, entering = static_cast<int>(j);
    }
    if (entering < 0 || sol.iterations >= options.max_iterations) {
      sol.status = entering < 0 ? QpStatus::optimal : QpStatus::max_iterations;
      sol.message = entering < 0 ? "optimal" : "reached max_iterations";
      break;
    }
    state[static_cast<size_t>(entering)] = State::free;
    free.push_back(entering);
    ++sol.iterations;
  }
  if (sol.status == QpStatus::optimal && !free.empty()) {
    // x = -H^-1 (g + M'v) keeps the free rows only to ~cond(H) eps |x|: refined on an independent
    // subset of them (working_set_refinement.hpp); the dependent rest, the rows at a bound and the
    // free multipliers' box must still hold.
    const Eigen::ColPivHouseholderQR<MatrixXd> qr(rows.M(free, Eigen::all).transpose());
    std::vector<int> basis, rest;
    for (Index k = 0; k < static_cast<Index>(free.size()); ++k)
      (k < qr.rank() ? basis : rest).push_back(free[static_cast<size_t>(qr.colsPermutation().indices()[k])]);
    VectorXd g_fixed = at_bound_sum();
    for (int j : rest) g_fixed += v[j] * rows.M.row(j).transpose();
    const auto others_hold = [&](const VectorXd& z) {
      const VectorXd r = rows.M * z - rows.r;
      for (Index j = 0; j < N; ++j) {
        const State st = state[static_cast<size_t>(j)];
        const double scaled = r[j] / row_scale[j];
        if ((st == State::lower && scaled > options.feasibility_tolerance) || (st == State::upper && -scaled > options.feasibility_tolerance))
          return false;
      }
      for (int j : rest)
        if (std::abs(r[j] / row_scale[j]) > options.feasibility_tolerance) return false;
      return true;
    };
    VectorXd x_refined = x, u = -v(basis);  // H x + g + M'v = 0: u = -v in the refinement's form H x + g - N u = 0
    refine_on_working_set(qp.hessian, g_fixed, rows.M(basis, Eigen::all).transpose(), rows.r(basis), others_hold, x_refined, u);
    bool in_box = true;
    for (size_t k = 0; k < basis.size(); ++k)
      in_box = in_box && -u[static_cast<Index>(k)] >= rows.lo[basis[k]] && -u[static_cast<Index>(k)] <= rows.hi[basis[k]];
    if (in_box) x = x_refined, v(basis) = -u;
  }
  sol.x = x;
  out.sigma = v.head(K);
  sol.objective = qp.objective(x) + terms.weights.dot((terms.matrix * x - terms.rhs).cwiseMax(0.0));
  sol.equality_multipliers = VectorXd::Zero(qp.equality_rhs.size());
  sol.inequality_multipliers = VectorXd::Zero(qp.inequality_rhs.size());
  sol.lower_bound_multipliers = VectorXd::Zero(n);
  sol.upper_bound_multipliers = VectorXd::Zero(n);
  for (Index j = K; j < N; ++j) {
    const int i = rows.index[static_cast<size_t>(j)];
    const bool in_working = state[static_cast<size_t>(j)] == State::free;
    switch (rows.kind[static_cast<size_t>(j)]) {
      case Kind::inequality:
        sol.inequality_multipliers[i] = v[j];
        if (in_working) sol.working_set.inequalities.push_back(i);
        break;
      case Kind::upper_bound:
        sol.upper_bound_multipliers[i] = v[j];
        if (in_working) sol.working_set.upper_bounds.push_back(i);
        break;
      case Kind::lower_bound:
        sol.lower_bound_multipliers[i] = v[j];
        if (in_working) sol.working_set.lower_bounds.push_back(i);
        break;
      case Kind::equality: sol.equality_multipliers[i] = v[j]; break;
      case Kind::term: break;
    }
  }
  return out;
}

}  // namespace cyclopt::qp
