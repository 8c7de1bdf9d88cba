#pragma once
// QPs for the solver tests: the unconstrained shell and random feasible QPs with degenerate
// active sets and (optionally) semidefinite Hessians.
#include "cyclopt/qp/quadratic_program.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <random>

namespace cyclopt::qp::testing {

using Eigen::MatrixXd;
using Eigen::VectorXd;

inline QuadraticProgram unconstrained(const MatrixXd& H, const VectorXd& g) {
  QuadraticProgram qp;
  qp.hessian = H;
  qp.gradient = g;
  qp.equality_matrix = MatrixXd(0, g.size());
  qp.inequality_matrix = MatrixXd(0, g.size());
  return qp;
}

// A random feasible QP: a known feasible point x0 makes some inequalities and bounds exactly
// active (degenerate), H has random rank (semidefinite when rank < n; then all bounds are finite).
inline QuadraticProgram random_qp(std::mt19937_64& rng, bool* semidefinite) {
  std::uniform_int_distribution<int> size(1, 10);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const int n = size(rng);
  const int rank = std::uniform_int_distribution<int>(0, n)(rng);
  *semidefinite = rank < n;
  const int m_eq = std::uniform_int_distribution<int>(0, n / 2)(rng);
  const int m_in = std::uniform_int_distribution<int>(0, 2 * n)(rng);
  MatrixXd F = MatrixXd::NullaryExpr(rank, n, [&] { return normal(rng); });
  QuadraticProgram qp = unconstrained(F.transpose() * F, VectorXd::NullaryExpr(n, [&] { return 3.0 * normal(rng); }));
  const VectorXd x0 = VectorXd::NullaryExpr(n, [&] { return normal(rng); });
  qp.equality_matrix = MatrixXd::NullaryExpr(m_eq, n, [&] { return normal(rng); });
  if (m_eq > 1 && uniform(rng) < 0.3) qp.equality_matrix.row(m_eq - 1) = 2.0 * qp.equality_matrix.row(0);  // redundant row
  qp.equality_rhs = qp.equality_matrix * x0;
  qp.inequality_matrix = MatrixXd::NullaryExpr(m_in, n, [&] { return normal(rng); });
  qp.inequality_rhs = qp.inequality_matrix * x0;
  for (int i = 0; i < m_in; ++i)
    if (uniform(rng) < 0.6) qp.inequality_rhs[i] += uniform(rng);
  qp.lower_bounds = x0 - VectorXd::NullaryExpr(n, [&] { return uniform(rng) < 0.2 ? 0.0 : 2.0 * uniform(rng); });
  qp.upper_bounds = x0 + VectorXd::NullaryExpr(n, [&] { return uniform(rng) < 0.2 ? 0.0 : 2.0 * uniform(rng); });
  if (!*semidefinite)
    for (int i = 0; i < n; ++i) {
      if (uniform(rng) < 0.4) qp.lower_bounds[i] = -std::numeric_limits<double>::infinity();
      if (uniform(rng) < 0.4) qp.upper_bounds[i] = std::numeric_limits<double>::infinity();
    }
  return qp;
}

// Ill-conditioned H, as the SQP's W_1 from (6.24) with eigenvalues clamped at sqrt(eps) lambda_max
// (cond ~1e8), one equality and n inequalities feasible at a random point.
inline QuadraticProgram ill_conditioned_qp(std::mt19937_64& rng, int n) {
  std::normal_distribution<double> normal;
  const MatrixXd Q = Eigen::HouseholderQR<MatrixXd>(MatrixXd::NullaryExpr(n, n, [&] { return normal(rng); })).householderQ();
  VectorXd eigenvalues = VectorXd::NullaryExpr(n, [&] { return std::exp(2.0 * normal(rng)); });
  for (int i = 0; i < n; i += 2) eigenvalues[i] = 1.5e-8 * eigenvalues.maxCoeff();
  QuadraticProgram qp = unconstrained(Q * eigenvalues.asDiagonal() * Q.transpose(), VectorXd::NullaryExpr(n, [&] { return normal(rng); }));
  const VectorXd x0 = VectorXd::NullaryExpr(n, [&] { return 3.0 * normal(rng); });
  qp.equality_matrix = MatrixXd::NullaryExpr(1, n, [&] { return normal(rng); });
  qp.equality_rhs = qp.equality_matrix * x0;
  qp.inequality_matrix = MatrixXd::NullaryExpr(n, n, [&] { return normal(rng); });
  qp.inequality_rhs = qp.inequality_matrix * x0 + VectorXd::NullaryExpr(n, [&] { return std::abs(normal(rng)); });
  return qp;
}

// n variables, clusters of 10 nearly parallel rows with right-hand sides spread over [0, 10]:
// rows of (6.7) for one constraint kind on neighbouring grid points. Unconstrained minimiser far
// outside, so several rows - some initially screened out - are active at the optimum.
inline QuadraticProgram many_row_qp(std::mt19937_64& rng, int n, int clusters) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 10.0);
  QuadraticProgram qp;
  const MatrixXd R = MatrixXd::NullaryExpr(n, n, [&] { return normal(rng); });
  qp.hessian = R.transpose() * R + 0.1 * MatrixXd::Identity(n, n);
  qp.gradient = 20.0 * VectorXd::NullaryExpr(n, [&] { return normal(rng); });
  qp.equality_matrix = MatrixXd::NullaryExpr(1, n, [&] { return normal(rng); });
  qp.equality_rhs = VectorXd::Zero(1);
  qp.inequality_matrix.resize(10 * clusters, n);
  qp.inequality_rhs.resize(10 * clusters);
  for (int c = 0; c < clusters; ++c) {
    const VectorXd a = VectorXd::NullaryExpr(n, [&] { return normal(rng); }).normalized();
    const double b = uniform(rng);
    for (int k = 0; k < 10; ++k) {
      qp.inequality_matrix.row(10 * c + k) = (a + 1e-3 * VectorXd::NullaryExpr(n, [&] { return normal(rng); })).transpose();
      qp.inequality_rhs[10 * c + k] = b + 1e-4 * k;
    }
  }
  qp.lower_bounds = VectorXd::Constant(n, -3.0);
  qp.upper_bounds = VectorXd::Constant(n, 3.0);
  return qp;
}

}  // namespace cyclopt::qp::testing
