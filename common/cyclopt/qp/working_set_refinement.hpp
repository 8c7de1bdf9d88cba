#pragma once
// Iterative refinement of a dual active-set method's solution on its working set. The dual
// methods (dual_active_set_solver.hpp, positive_part_qp.hpp) build x from multipliers through H^-1
// and keep the working rows only to ~cond(H) eps |x|: with the SQP's W_1 of (6.24), whose
// eigenvalues are clamped at sqrt(eps) lambda_max, that is ~1e-7, and a QP step that leaves the
// linearised constraints violated by that much cannot bring the SQP's violation below it. Newton
// corrections of the equality-constrained KKT system of the working rows n_j'x = c_j,
//   H x + g - N u = 0,   N' x = c,
// by a full-pivot LU of [H -N; N' 0], restore the rows to rounding.

#include <Eigen/Core>
#include <Eigen/LU>

namespace cyclopt::qp {

// A correction of the drift is tiny; one larger than this (relative to |x|_inf, |u|_inf) comes from
// a nearly singular KKT matrix and is not taken.
inline constexpr double kMaxRefinementCorrection = 1e-4;

// normals: n x q (column j: n_j). At most two corrections; one is kept only if it lowers
// |N'x - c|_inf, is within kMaxRefinementCorrection and `keeps_other_rows(x)` holds for the
// corrected x (a callable taking const Eigen::VectorXd&). x and u are updated in place; nothing
// happens without rows or with dependent ones. (A template: each solver inlines it as its own code.)
template <class KeepsOtherRows>
void refine_on_working_set(const Eigen::MatrixXd& hessian, const Eigen::VectorXd& gradient, const Eigen::MatrixXd& normals,
                           const Eigen::VectorXd& rhs, const KeepsOtherRows& keeps_other_rows, Eigen::VectorXd& x,
                           Eigen::VectorXd& u) {
  using Eigen::Index;
  const Index n = x.size(), q = normals.cols();
  if (q == 0) return;
  const Eigen::MatrixXd& N = normals;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + q, n + q);
  K.topLeftCorner(n, n) = hessian;
  K.topRightCorner(n, q) = -N;
  K.bottomLeftCorner(q, n) = N.transpose();
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
  if (!lu.isInvertible()) return;  // dependent working normals: keep the method's solution
  auto working_residual = [&](const Eigen::VectorXd& z) { return (N.transpose() * z - rhs).lpNorm<Eigen::Infinity>(); };
  for (int pass = 0; pass < 2; ++pass) {
    Eigen::VectorXd r(n + q);
    r.head(n) = -(hessian * x + gradient - N * u);
    r.tail(q) = rhs - N.transpose() * x;
    const Eigen::VectorXd delta = lu.solve(r);
    if (!delta.allFinite() || delta.head(n).lpNorm<Eigen::Infinity>() > kMaxRefinementCorrection * (1.0 + x.lpNorm<Eigen::Infinity>()) ||
        delta.tail(q).lpNorm<Eigen::Infinity>() > kMaxRefinementCorrection * (1.0 + u.lpNorm<Eigen::Infinity>()))
      return;
    const Eigen::VectorXd refined = x + delta.head(n);
    if (!(working_residual(refined) < working_residual(x)) || !keeps_other_rows(refined)) return;
    x = refined;
    u += delta.tail(q);
  }
}

}  // namespace cyclopt::qp
