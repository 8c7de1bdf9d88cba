#include "cyclopt/foot_fit/arrow_least_squares.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace cyclopt::foot_fit {
namespace {

// The blocks of J^T J and J^T r: a_j = |J_l,j|^2, b_j = J_l,j^T J_g,j (row j of B), C = J_g^T J_g.
struct NormalBlocks {
  Eigen::VectorXd a, local_gradient, global_gradient;
  Eigen::MatrixXd B, C;
};

NormalBlocks normal_blocks(const ArrowEvaluation& ev) {
  const int n = static_cast<int>(ev.r.cols());
  const Eigen::Index g = ev.global_jacobian.cols();
  NormalBlocks nb;
  nb.a.resize(n);
  nb.local_gradient.resize(n);
  nb.B.resize(n, g);
  for (int j = 0; j < n; ++j) {
    nb.a[j] = ev.local_jacobian.col(j).squaredNorm();
    nb.local_gradient[j] = ev.local_jacobian.col(j).dot(ev.r.col(j));
    nb.B.row(j) = ev.local_jacobian.col(j).transpose() * ev.global_jacobian.middleRows(2 * j, 2);
  }
  const Eigen::Map<const Eigen::VectorXd> r_flat(ev.r.data(), 2 * n);
  nb.global_gradient = ev.global_jacobian.transpose() * r_flat;
  nb.C = ev.global_jacobian.transpose() * ev.global_jacobian;
  return nb;
}

std::vector<Eigen::Index> indices_of(const Eigen::Array<bool, Eigen::Dynamic, 1>& free) {
  std::vector<Eigen::Index> idx;
  for (Eigen::Index i = 0; i < free.size(); ++i)
    if (free[i]) idx.push_back(i);
  return idx;
}

// The free globals' block of S = C + lambda D_g - sum_j b_j^T b_j / (a_j + lambda D_l,j) and, with
// `rhs`, of -g_g + sum_j b_j^T g_l,j / (a_j + lambda D_l,j), for the globals `free` (fixed or held
// ones never enter a step); with `lower_only` only its lower triangle, all that the LDLT of a step
// reads (the upper one keeps C). Element by element, in place: the solver's hot loop.
Eigen::MatrixXd schur(const NormalBlocks& nb, const Eigen::VectorXd& local_diag, const Eigen::VectorXd& global_diag,
                      double lambda, const std::vector<Eigen::Index>& free, bool lower_only, Eigen::VectorXd* rhs) {
  const Eigen::Index F = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd S(F, F);
  for (Eigen::Index c = 0; c < F; ++c)
    for (Eigen::Index r = 0; r < F; ++r) S(r, c) = nb.C(free[r], free[c]);
  for (Eigen::Index a = 0; a < F; ++a) S(a, a) += lambda * global_diag[free[a]];
  if (rhs) {
    rhs->resize(F);
    for (Eigen::Index a = 0; a < F; ++a) (*rhs)[a] = -nb.global_gradient[free[a]];
  }
  Eigen::VectorXd b(F);
  for (Eigen::Index j = 0; j < nb.a.size(); ++j) {
    const double aj = nb.a[j] + lambda * local_diag[j];
    if (aj <= 0.0) continue;
    for (Eigen::Index a = 0; a < F; ++a) b[a] = nb.B(j, free[a]);
    for (Eigen::Index c = 0; c < F; ++c)
      for (Eigen::Index r = lower_only ? c : 0; r < F; ++r) S(r, c) -= b[r] * b[c] / aj;
    if (rhs) *rhs += b * (nb.local_gradient[j] / aj);
  }
  return S;
}

}  // namespace

ArrowSummary solve_arrow_least_squares(const ArrowResidual& residual, Eigen::VectorXd& global, Eigen::VectorXd& local,
                                       const Eigen::VectorXd& lower, const Eigen::VectorXd& upper, const ArrowOptions& o) {
  const Eigen::Index G = global.size(), N = local.size();
  if (lower.size() != G || upper.size() != G) throw std::invalid_argument("arrow least squares: bounds and globals differ in size");
  for (Eigen::Index i = 0; i < G; ++i)
    if (!(lower[i] <= upper[i])) throw std::invalid_argument("arrow least squares: lower bound above upper bound at global " + std::to_string(i));
  global = global.cwiseMax(lower).cwiseMin(upper);
  ArrowSummary s;
  ArrowEvaluation ev, trial;
  ++s.evaluations;
  if (!residual(global, local, true, ev)) throw std::invalid_argument("arrow least squares: the start cannot be evaluated");
  s.initial_cost = s.cost = 0.5 * ev.r.squaredNorm();
  double lambda = -1.0;
  s.message = "iteration limit reached";
  Eigen::Array<bool, Eigen::Dynamic, 1> free(G);
  for (s.iterations = 0; s.iterations < o.max_iterations; ++s.iterations) {
    if (s.cost <= o.zero_cost) {
      s.converged = true;
      s.message = "residual zero to rounding";
      break;
    }
    const NormalBlocks nb = normal_blocks(ev);
    for (Eigen::Index i = 0; i < G; ++i)
      free[i] = lower[i] < upper[i] && !(global[i] <= lower[i] && nb.global_gradient[i] > 0.0) &&
                !(global[i] >= upper[i] && nb.global_gradient[i] < 0.0);
    // Marquardt scaling by the diagonal of J^T J, floored so unidentifiable unknowns stay damped.
    const double largest = std::max(nb.a.size() ? nb.a.maxCoeff() : 0.0, nb.C.size() ? nb.C.diagonal().maxCoeff() : 0.0);
    const double floor = 1e-12 * std::max(largest, 1e-300);
    const Eigen::VectorXd dl = nb.a.cwiseMax(floor), dg = nb.C.diagonal().cwiseMax(floor);
    if (lambda < 0.0) lambda = o.initial_damping;
    // The step of the damped normal equations at `lam` (projected onto the bounds when
    // `project`) and the decrease the Gauss-Newton model predicts for it: -(g^T d + 1/2 |J d|^2).
    // With `in_standard_errors`, also the largest |step| of a free global in units of its
    // standard error, sigma^2 (S_f^-1)_aa with sigma^2 = |r|^2 / (2N - N - F) (residuals minus
    // unknowns).
    struct Step {
      Eigen::VectorXd global, local;
      double predicted;
      double largest_in_standard_errors = std::numeric_limits<double>::quiet_NaN();
    };
    auto step_at = [&](double lam, bool project, bool in_standard_errors = false) {
      const std::vector<Eigen::Index> idx = indices_of(free);
      const Eigen::Index F = static_cast<Eigen::Index>(idx.size());
      Eigen::VectorXd rf;
      const Eigen::MatrixXd Sf = schur(nb, dl, dg, lam, idx, true, &rf);
      Step st{Eigen::VectorXd::Zero(G), Eigen::VectorXd(N), 0.0};
      const Eigen::LDLT<Eigen::MatrixXd, Eigen::Lower> ldlt(Sf);
      const Eigen::VectorXd xf = F > 0 ? Eigen::VectorXd(ldlt.solve(rf)) : Eigen::VectorXd();
      for (Eigen::Index a = 0; a < F; ++a) st.global[idx[a]] = xf[a];
      const Eigen::Index dof = N - F;
      if (in_standard_errors && F > 0 && dof > 0) {
        const double sigma2 = 2.0 * s.cost / double(dof);
        const Eigen::VectorXd variance = sigma2 * ldlt.solve(Eigen::MatrixXd::Identity(F, F)).diagonal();
        st.largest_in_standard_errors = 0.0;
        for (Eigen::Index a = 0; a < F; ++a)
          st.largest_in_standard_errors = std::max(st.largest_in_standard_errors, std::abs(xf[a]) / std::sqrt(variance[a]));
      }
      if (project) st.global = (global + st.global).cwiseMax(lower).cwiseMin(upper) - global;
      for (Eigen::Index j = 0; j < N; ++j)
        st.local[j] = -(nb.local_gradient[j] + nb.B.row(j).dot(st.global)) / (nb.a[j] + lam * dl[j]);
      double jd2 = 0.0;
      for (Eigen::Index j = 0; j < N; ++j) {
        Eigen::Vector2d jd = ev.local_jacobian.col(j) * st.local[j];
        jd.noalias() += ev.global_jacobian.middleRows(2 * j, 2) * st.global;
        jd2 += jd.squaredNorm();
      }
      st.predicted = -(nb.global_gradient.dot(st.global) + nb.local_gradient.dot(st.local) + 0.5 * jd2);
      return st;
    };
    // Stationarity: the unprojected Gauss-Newton step in the free unknowns, 1/2 g^T (J^T J)^-1 g,
    // promises almost nothing (projection could only lower a decrease that is already tiny).
    const Step gauss_newton = step_at(1e-12, false, o.parameter_tolerance > 0.0);
    if (gauss_newton.global.allFinite() && gauss_newton.local.allFinite() &&
        gauss_newton.predicted >= 0.0 && gauss_newton.predicted <= o.function_tolerance * s.cost) {
      s.converged = true;
      s.message = "Gauss-Newton predicted decrease below function_tolerance * cost";
      break;
    }
    // Statistical stationarity: the Gauss-Newton step would move no free global by as much as
    // parameter_tolerance of its standard error.
    if (gauss_newton.global.allFinite() && gauss_newton.predicted >= 0.0 &&
        gauss_newton.largest_in_standard_errors <= o.parameter_tolerance) {
      s.converged = true;
      s.message = "Gauss-Newton step below parameter_tolerance standard errors";
      break;
    }
    bool accepted = false;
    while (!accepted) {
      const Step st = step_at(lambda, true);
      const Eigen::VectorXd new_global = global + st.global, new_local = local + st.local;
      const bool valid = st.local.allFinite() && st.global.allFinite();
      ++s.evaluations;
      // Trial points are evaluated without the Jacobian; an accepted one is evaluated again with it.
      bool better = valid && residual(new_global, new_local, false, trial) && 0.5 * trial.r.squaredNorm() < s.cost;
      if (better) {
        ++s.evaluations;
        better = residual(new_global, new_local, true, trial);
      }
      if (better) {
        const double new_cost = 0.5 * trial.r.squaredNorm();
        const double step = std::max(st.global.lpNorm<Eigen::Infinity>(), N ? st.local.lpNorm<Eigen::Infinity>() : 0.0);
        const double size = std::max(global.lpNorm<Eigen::Infinity>(), N ? local.lpNorm<Eigen::Infinity>() : 0.0);
        const double rho = st.predicted > 0.0 ? (s.cost - new_cost) / st.predicted : 0.0;
        global = new_global;
        local = new_local;
        std::swap(ev, trial);
        const double old_cost = s.cost;
        s.cost = new_cost;
        lambda *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3));
        accepted = true;
        if (old_cost - new_cost <= o.function_tolerance * new_cost && st.predicted <= o.function_tolerance * new_cost) {
          s.converged = true;  // MINPACK's ftol test: neither the step nor its model gains more
          s.message = "relative decrease below function_tolerance";
        } else if (step <= o.step_tolerance * (1.0 + size)) {
          s.converged = true;
          s.message = "step below step_tolerance";
        }
      } else {
        lambda *= 4.0;
        if (lambda > o.max_damping) {
          s.message = "no decrease up to the largest damping";
          break;
        }
      }
    }
    if (!accepted || s.converged) {
      if (s.converged) ++s.iterations;
      break;
    }
  }
  const NormalBlocks nb = normal_blocks(ev);
  for (Eigen::Index i = 0; i < G; ++i)
    free[i] = lower[i] < upper[i] && !(global[i] <= lower[i] && nb.global_gradient[i] > 0.0) &&
              !(global[i] >= upper[i] && nb.global_gradient[i] < 0.0);
  const std::vector<Eigen::Index> idx = indices_of(free);
  const Eigen::MatrixXd Sf = schur(nb, Eigen::VectorXd::Zero(N), Eigen::VectorXd::Zero(G), 0.0, idx, false, nullptr);
  s.reduced_normal_matrix = Eigen::MatrixXd::Zero(G, G);
  for (std::size_t a = 0; a < idx.size(); ++a)
    for (std::size_t b = 0; b < idx.size(); ++b) s.reduced_normal_matrix(idx[a], idx[b]) = Sf(a, b);
  s.free = free;
  return s;
}

}  // namespace cyclopt::foot_fit
