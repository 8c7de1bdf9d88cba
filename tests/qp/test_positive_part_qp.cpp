// The dual solver of QPs with positive-part terms (positive_part_qp.hpp) against the elastic
// formulation of the same problem - t_k >= a_k'x - b_k, t_k >= 0, cost w_k t_k - solved by the
// primal active-set method: the same optimal value, a feasible x, subgradients sigma in [0, w] that
// make the Lagrangian stationary. Random problems include the degenerate shape of a held joint
// (many terms on few directions, vanishing together) and infeasible constraint sets.
#include "cyclopt/qp/active_set_solver.hpp"
#include "cyclopt/qp/positive_part_qp.hpp"
#include "random_qp.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cstdio>
#include <limits>
#include <random>

namespace {

using cyclopt::qp::PositivePartQpSolution;
using cyclopt::qp::PositivePartTerms;
using cyclopt::qp::QpSolution;
using cyclopt::qp::QpStatus;
using cyclopt::qp::QuadraticProgram;
using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kInf = std::numeric_limits<double>::infinity();

// The elastic QP in (x, t).
QuadraticProgram elastic(const QuadraticProgram& qp, const PositivePartTerms& terms) {
  const Eigen::Index n = qp.num_variables(), K = terms.rhs.size();
  QuadraticProgram e;
  e.hessian = MatrixXd::Zero(n + K, n + K);
  e.hessian.topLeftCorner(n, n) = qp.hessian;
  e.gradient.resize(n + K);
  e.gradient << qp.gradient, terms.weights;
  e.equality_matrix = MatrixXd::Zero(qp.equality_rhs.size(), n + K);
  e.equality_matrix.leftCols(n) = qp.equality_matrix;
  e.equality_rhs = qp.equality_rhs;
  const Eigen::Index m = qp.inequality_rhs.size();
  e.inequality_matrix = MatrixXd::Zero(m + K, n + K);
  e.inequality_matrix.topLeftCorner(m, n) = qp.inequality_matrix;
  e.inequality_matrix.bottomLeftCorner(K, n) = terms.matrix;
  e.inequality_matrix.bottomRightCorner(K, K) = -MatrixXd::Identity(K, K);
  e.inequality_rhs.resize(m + K);
  e.inequality_rhs << qp.inequality_rhs, terms.rhs;
  e.lower_bounds.resize(n + K);
  e.lower_bounds << qp.lower_bounds, VectorXd::Zero(K);
  e.upper_bounds.resize(n + K);
  e.upper_bounds << qp.upper_bounds, VectorXd::Constant(K, kInf);
  return e;
}

// A strictly convex random QP with finite or infinite bounds and K terms; held: the terms' rows lie
// in a 2-dimensional subspace and vanish together at a feasible point x0 (a held joint's samples).
void random_problem(std::mt19937_64& rng, bool held, QuadraticProgram& qp, PositivePartTerms& terms) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const int n = 2 + static_cast<int>(rng() % 7), K = 1 + static_cast<int>(rng() % 25), m_in = static_cast<int>(rng() % 8);
  const int m_eq = static_cast<int>(rng() % 2);
  const MatrixXd F = MatrixXd::NullaryExpr(n, n, [&] { return normal(rng); });
  qp = cyclopt::qp::testing::unconstrained(F.transpose() * F + 0.1 * MatrixXd::Identity(n, n),
                                           VectorXd::NullaryExpr(n, [&] { return 2.0 * normal(rng); }));
  const VectorXd x0 = VectorXd::NullaryExpr(n, [&] { return normal(rng); });
  qp.equality_matrix = MatrixXd::NullaryExpr(m_eq, n, [&] { return normal(rng); });
  qp.equality_rhs = qp.equality_matrix * x0;
  qp.inequality_matrix = MatrixXd::NullaryExpr(m_in, n, [&] { return normal(rng); });
  qp.inequality_rhs = qp.inequality_matrix * x0 + VectorXd::NullaryExpr(m_in, [&] { return uniform(rng) < 0.4 ? 0.0 : uniform(rng); });
  qp.lower_bounds = VectorXd::Constant(n, -kInf);
  qp.upper_bounds = VectorXd::Constant(n, kInf);
  for (int j = 0; j < n; ++j) {
    if (uniform(rng) < 0.3) qp.lower_bounds[j] = x0[j] - uniform(rng);
    if (uniform(rng) < 0.3) qp.upper_bounds[j] = x0[j] + uniform(rng);
  }
  if (held) {
    const MatrixXd basis = MatrixXd::NullaryExpr(2, n, [&] { return normal(rng); });
    terms.matrix = MatrixXd::NullaryExpr(K, 2, [&] { return normal(rng); }) * basis;
    terms.rhs = terms.matrix * x0;
  } else {
    terms.matrix = MatrixXd::NullaryExpr(K, n, [&] { return normal(rng); });
    terms.rhs = VectorXd::NullaryExpr(K, [&] { return normal(rng); });
  }
  terms.weights = VectorXd::NullaryExpr(K, [&] { return 0.05 + 2.0 * uniform(rng); });
}

TEST(PositivePartQp, SameOptimumAsTheElasticFormulation) {
  std::mt19937_64 rng(52);
  for (int k = 0; k < 300; ++k) {
    SCOPED_TRACE("problem " + std::to_string(k));
    QuadraticProgram qp;
    PositivePartTerms terms;
    random_problem(rng, k % 2 == 1, qp, terms);
    const PositivePartQpSolution s = cyclopt::qp::solve_positive_part_qp(qp, terms);
    const QpSolution reference = cyclopt::qp::solve_active_set(elastic(qp, terms));
    ASSERT_EQ(reference.status, QpStatus::optimal) << reference.message;
    ASSERT_EQ(s.qp.status, QpStatus::optimal) << s.qp.message;
    const double scale = 1.0 + std::abs(reference.objective);
    EXPECT_NEAR(s.qp.objective, reference.objective, 1e-8 * scale);
    // Feasible, sigma in its box, and the Lagrangian stationary with the returned multipliers.
    const VectorXd& x = s.qp.x;
    if (qp.equality_rhs.size()) {
      EXPECT_LE((qp.equality_matrix * x - qp.equality_rhs).lpNorm<Eigen::Infinity>(), 1e-8);
    }
    if (qp.inequality_rhs.size()) {
      EXPECT_LE((qp.inequality_matrix * x - qp.inequality_rhs).maxCoeff(), 1e-8);
    }
    EXPECT_GE(s.sigma.minCoeff(), 0.0);
    EXPECT_LE((s.sigma - terms.weights).maxCoeff(), 0.0);
    const VectorXd stationarity = qp.hessian * x + qp.gradient + terms.matrix.transpose() * s.sigma +
                                  qp.equality_matrix.transpose() * s.qp.equality_multipliers +
                                  qp.inequality_matrix.transpose() * s.qp.inequality_multipliers -
                                  s.qp.lower_bound_multipliers + s.qp.upper_bound_multipliers;
    EXPECT_LE(stationarity.lpNorm<Eigen::Infinity>(), 1e-8 * (1.0 + qp.gradient.lpNorm<Eigen::Infinity>()));
    // sigma_k is w_k where the piece is positive, 0 where negative.
    const VectorXd piece = terms.matrix * x - terms.rhs;
    for (Eigen::Index t = 0; t < piece.size(); ++t) {
      if (piece[t] > 1e-7) {
        EXPECT_NEAR(s.sigma[t], terms.weights[t], 1e-9);
      }
      if (piece[t] < -1e-7) {
        EXPECT_NEAR(s.sigma[t], 0.0, 1e-9);
      }
    }
  }
}

// The dual has simple bounds only, so any start is admissible: from random sigma (at 0, at w or
// between) and random active rows - dependent rows of a held joint included - the same optimum.
TEST(PositivePartQp, AnyStartGivesTheSameOptimum) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    SCOPED_TRACE("problem " + std::to_string(k));
    QuadraticProgram qp;
    PositivePartTerms terms;
    random_problem(rng, k % 2 == 1, qp, terms);
    const PositivePartQpSolution cold = cyclopt::qp::solve_positive_part_qp(qp, terms);
    ASSERT_EQ(cold.qp.status, QpStatus::optimal);
    cyclopt::qp::PositivePartQpStart start;
    start.sigma = VectorXd::NullaryExpr(terms.rhs.size(), [&] {
      const double r = uniform(rng);
      return r < 0.3 ? 0.0 : (r < 0.6 ? 1e9 : uniform(rng));
    });
    for (Eigen::Index i = 0; i < qp.inequality_rhs.size(); ++i)
      if (uniform(rng) < 0.5) start.active.inequalities.push_back(static_cast<int>(i));
    const PositivePartQpSolution warm = cyclopt::qp::solve_positive_part_qp(qp, terms, {}, start);
    ASSERT_EQ(warm.qp.status, QpStatus::optimal) << warm.qp.message;
    EXPECT_NEAR(warm.qp.objective, cold.qp.objective, 1e-9 * (1.0 + std::abs(cold.qp.objective)));
    EXPECT_LE((warm.qp.x - cold.qp.x).lpNorm<Eigen::Infinity>(), 1e-6 * (1.0 + cold.qp.x.lpNorm<Eigen::Infinity>()));
  }
}

// Ill-conditioned H (random_qp.hpp, as the SQP's W_1 from (6.24)) with terms vanishing near the
// solution: x = -H^-1 (g + M'v) alone keeps the free rows - the working constraints and the terms
// with sigma inside (0, w), held at their kink - only to ~cond(H) eps |x| (1e-7); refined on them
// (working_set_refinement.hpp), to rounding.
TEST(PositivePartQp, FreeRowsHoldToRoundingWhenTheHessianIsIllConditioned) {
  std::mt19937_64 rng(71);
  std::normal_distribution<double> normal;
  double worst = 0.0;
  int held = 0;
  for (int k = 0; k < 200; ++k) {
    SCOPED_TRACE("problem " + std::to_string(k));
    const int n = 4 + k % 8;
    const QuadraticProgram qp = cyclopt::qp::testing::ill_conditioned_qp(rng, n);
    PositivePartTerms terms;
    terms.matrix = MatrixXd::NullaryExpr(n, n, [&] { return normal(rng); });
    terms.rhs = VectorXd::NullaryExpr(n, [&] { return 0.1 * normal(rng); });
    terms.weights = VectorXd::NullaryExpr(n, [&] { return 0.5 + std::abs(normal(rng)); });
    const PositivePartQpSolution s = cyclopt::qp::solve_positive_part_qp(qp, terms);
    ASSERT_EQ(s.qp.status, QpStatus::optimal) << s.qp.message;
    double residual = std::abs((qp.equality_matrix * s.qp.x - qp.equality_rhs)[0]);
    for (int i : s.qp.working_set.inequalities)
      residual = std::max(residual, std::abs(qp.inequality_matrix.row(i).dot(s.qp.x) - qp.inequality_rhs[i]));
    for (Eigen::Index t = 0; t < terms.rhs.size(); ++t)
      if (s.sigma[t] > 0.0 && s.sigma[t] < terms.weights[t]) {
        residual = std::max(residual, std::abs(terms.matrix.row(t).dot(s.qp.x) - terms.rhs[t]));
        ++held;
      }
    worst = std::max(worst, residual / (1.0 + s.qp.x.lpNorm<Eigen::Infinity>()));
  }
  std::printf("ill-conditioned QPs with %d terms at their kink: largest free-row residual %.1e relative to |x|\n", held, worst);
  EXPECT_GT(held, 100);
  EXPECT_LE(worst, 1e-13);
}

TEST(PositivePartQp, InconsistentConstraintsAreInfeasible) {
  QuadraticProgram qp = cyclopt::qp::testing::unconstrained(MatrixXd::Identity(2, 2), VectorXd::Zero(2));
  qp.inequality_matrix = (MatrixXd(2, 2) << 1.0, 0.0, -1.0, 0.0).finished();  // x1 <= -1 and x1 >= 1
  qp.inequality_rhs = (VectorXd(2) << -1.0, -1.0).finished();
  PositivePartTerms terms{(MatrixXd(1, 2) << 0.0, 1.0).finished(), VectorXd::Zero(1), VectorXd::Ones(1)};
  EXPECT_EQ(cyclopt::qp::solve_positive_part_qp(qp, terms).qp.status, QpStatus::infeasible);
}

}  // namespace
