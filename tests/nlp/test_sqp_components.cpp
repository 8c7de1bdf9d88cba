// The building blocks of the seed's SQP, each against an independent property.
#include "cyclopt/nlp/active_set_projections.hpp"
#include "cyclopt/nlp/damped_bfgs.hpp"
#include "cyclopt/nlp/l1_merit.hpp"
#include "cyclopt/nlp/sqp_subproblems.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cstdio>
#include <limits>
#include <random>

namespace {

using namespace cyclopt::nlp;
using Eigen::MatrixXd;
using Eigen::VectorXd;

double min_eigenvalue(const MatrixXd& W) { return Eigen::SelfAdjointEigenSolver<MatrixXd>(W).eigenvalues().minCoeff(); }

TEST(DampedBfgs, SecantConditionWithPositiveCurvature) {
  std::mt19937_64 rng(1);
  std::normal_distribution<double> normal;
  for (int k = 0; k < 50; ++k) {
    const MatrixXd F = MatrixXd::NullaryExpr(5, 5, [&] { return normal(rng); });
    MatrixXd W = F.transpose() * F + MatrixXd::Identity(5, 5);
    const MatrixXd A = MatrixXd::NullaryExpr(5, 5, [&] { return normal(rng); });
    const VectorXd s = VectorXd::NullaryExpr(5, [&] { return normal(rng); });
    const VectorXd y = (A.transpose() * A + 5 * MatrixXd::Identity(5, 5)) * s;  // s'y > 0.2 s'Ws likely
    if (s.dot(y) < 0.2 * s.dot(W * s)) continue;
    damped_bfgs_update(W, s, y);
    EXPECT_LE((W * s - y).norm(), 1e-10 * y.norm());  // theta = 1: W_{k+1} s = y (eq. 6.22)
    EXPECT_GT(min_eigenvalue(W), 0.0);
  }
}

TEST(DampedBfgs, NegativeCurvatureIsDampedAndStaysPositiveDefinite) {
  MatrixXd W = MatrixXd::Identity(3, 3);
  const VectorXd s = VectorXd::Ones(3);
  const VectorXd y = -s;  // s'y < 0: undamped BFGS would lose definiteness
  damped_bfgs_update(W, s, y);
  EXPECT_GT(min_eigenvalue(W), 0.0);
  // r = theta y + (1 - theta) W s with theta = 0.8 s'Ws / (s'Ws - s'y) = 0.4 (eq. 6.21): W s = r.
  const VectorXd r = 0.4 * y + 0.6 * s;
  EXPECT_LE((W * s - r).norm(), 1e-12);
}

TEST(DampedBfgs, ScaledIdentityStartSatisfiesSecantCondition) {
  const VectorXd s = (VectorXd(2) << 1.0, 0.5).finished();
  const VectorXd y = (VectorXd(2) << 4.0, 1.0).finished();
  const MatrixXd W = scaled_identity_update(s, y);
  EXPECT_LE((W * s - y).norm(), 1e-12);  // y'y/s'y scaling keeps theta = 1 here
  EXPECT_GT(min_eigenvalue(W), 0.0);
}

TEST(ClampedHessian, RaisesSmallAndNegativeEigenvaluesToSqrtEpsTimesLargest) {
  const MatrixXd Q = Eigen::HouseholderQR<MatrixXd>(MatrixXd::Random(3, 3)).householderQ();
  const VectorXd eigenvalues = (VectorXd(3) << -2.0, 1e-12, 4.0).finished();
  const MatrixXd H = Q * eigenvalues.asDiagonal() * Q.transpose();
  const VectorXd clamped = Eigen::SelfAdjointEigenSolver<MatrixXd>(clamped_hessian(H)).eigenvalues();
  const double floor = std::sqrt(std::numeric_limits<double>::epsilon()) * 4.0;
  EXPECT_NEAR(clamped[0], floor, 1e-14);
  EXPECT_NEAR(clamped[1], floor, 1e-14);
  EXPECT_NEAR(clamped[2], 4.0, 1e-12);
  EXPECT_TRUE(clamped_hessian(-MatrixXd::Identity(2, 2)).isIdentity());
}

Evaluation sample_evaluation() {
  // f = x1 + 2 x2 at x = (1, 0); c_eq = x1 - 1 (value 0.5 here), c_in = (x2 - 1, -x2 + 0.25)
  Evaluation e;
  e.objective = 3.0;
  e.gradient = (VectorXd(2) << 1.0, 2.0).finished();
  e.equalities = (VectorXd(1) << 0.5).finished();
  e.equality_jacobian = (MatrixXd(1, 2) << 1.0, 0.0).finished();
  e.inequalities = (VectorXd(2) << -1.0, 0.25).finished();
  e.inequality_jacobian = (MatrixXd(2, 2) << 0.0, 1.0, 0.0, -1.0).finished();
  return e;
}

TEST(L1Merit, MeritViolationAndModelByHand) {
  const Evaluation e = sample_evaluation();
  const Penalties mu{(VectorXd(1) << 2.0).finished(), (VectorXd(2) << 3.0, 4.0).finished()};
  EXPECT_DOUBLE_EQ(mu.max(), 4.0);
  EXPECT_DOUBLE_EQ(l1_merit(e, mu), 3.0 + 2.0 * 0.5 + 4.0 * 0.25);  // eq. (6.6)
  const VectorXd d = (VectorXd(2) << -1.0, 0.5).finished();
  // J d + c: eq -0.5; in (-0.5, -0.25): eq. (6.11) = 0.5
  EXPECT_DOUBLE_EQ(linearized_violation(e, d), 0.5);
  const MatrixXd W = MatrixXd::Identity(2, 2);
  EXPECT_DOUBLE_EQ(l1_model(e, W, d, mu), 3.0 + (-1.0 + 1.0) + 0.5 * 1.25 + 2.0 * 0.5);  // eq. (6.8)
}

TEST(ActiveSetProjections, LeastSquaresMultipliersAreExactAtAKktPoint) {
  // grad f = -(J_eq' 2 + J_in,0' 3 + e_1 * 0.5): the least-squares multipliers recover (2, 3, 0.5).
  Evaluation e = sample_evaluation();
  e.gradient = -(e.equality_jacobian.transpose() * 2.0 + e.inequality_jacobian.row(0).transpose() * 3.0);
  e.gradient[1] -= 0.5;
  const LeastSquaresMultipliers y = least_squares_multipliers(e, {{0}, {1}});
  // Column 1 of the bound and the inequality row 0 are both e_2: dependent, so only their sum is defined.
  EXPECT_NEAR(y.equality[0], 2.0, 1e-12);
  EXPECT_NEAR(y.inequality[0] + y.bound[1], 3.5, 1e-12);
  EXPECT_DOUBLE_EQ(y.inequality[1], 0.0);
  const LeastSquaresMultipliers y2 = least_squares_multipliers(e, {{0}, {}});
  EXPECT_NEAR(y2.inequality[0], 3.5, 1e-12);
}

TEST(ActiveSetProjections, SecondOrderCorrectionIsTheShortestProjection) {
  const Evaluation e = sample_evaluation();
  const VectorXd d = second_order_correction(e, {1});  // equality and inequality 1 treated as equalities
  EXPECT_NEAR((e.equality_jacobian * d)[0] + e.equalities[0], 0.0, 1e-14);
  EXPECT_NEAR(e.inequality_jacobian.row(1).dot(d) + e.inequalities[1], 0.0, 1e-14);
  // Two independent constraints in 2-D: unique; with only the equality, the shortest step is along its gradient.
  const VectorXd d_eq = second_order_correction(e, {});
  EXPECT_NEAR(d_eq[0], -0.5, 1e-14);
  EXPECT_NEAR(d_eq[1], 0.0, 1e-14);
}

}  // namespace

namespace {

// The full l1-relaxed QP (6.13) with a slack on every inequality, built independently here.
cyclopt::qp::QuadraticProgram full_relaxed_program(const Evaluation& e, const MatrixXd& W, double mu) {
  const Eigen::Index n = W.rows(), m_eq = e.equalities.size(), m_in = e.inequalities.size(), total = n + 2 * m_eq + m_in;
  cyclopt::qp::QuadraticProgram qp;
  qp.hessian = MatrixXd::Zero(total, total);
  qp.hessian.topLeftCorner(n, n) = W;
  qp.gradient = VectorXd::Constant(total, mu);
  qp.gradient.head(n) = e.gradient;
  qp.equality_matrix = MatrixXd::Zero(m_eq, total);
  qp.equality_matrix << e.equality_jacobian, -MatrixXd::Identity(m_eq, m_eq), MatrixXd::Identity(m_eq, m_eq), MatrixXd::Zero(m_eq, m_in);
  qp.equality_rhs = -e.equalities;
  qp.inequality_matrix = MatrixXd::Zero(m_in, total);
  qp.inequality_matrix << e.inequality_jacobian, MatrixXd::Zero(m_in, 2 * m_eq), -MatrixXd::Identity(m_in, m_in);
  qp.inequality_rhs = -e.inequalities;
  qp.lower_bounds = VectorXd::Zero(total);
  qp.lower_bounds.head(n).setConstant(-std::numeric_limits<double>::infinity());
  return qp;
}

TEST(L1RelaxedSubproblem, SlacksOnDemandGiveTheFullProgramsOptimum) {
  std::mt19937_64 rng(42);
  std::normal_distribution<double> normal;
  int grown = 0;
  for (int k = 0; k < 200; ++k) {
    const int n = 3, m_eq = 1, m_in = 8;
    Evaluation e;
    e.objective = 0.0;
    e.gradient = VectorXd::NullaryExpr(n, [&] { return normal(rng); });
    e.equalities = VectorXd::NullaryExpr(m_eq, [&] { return normal(rng); });
    e.equality_jacobian = MatrixXd::NullaryExpr(m_eq, n, [&] { return normal(rng); });
    e.inequalities = VectorXd::NullaryExpr(m_in, [&] { return normal(rng); });
    e.inequality_jacobian = MatrixXd::NullaryExpr(m_in, n, [&] { return normal(rng); });
    const MatrixXd F = MatrixXd::NullaryExpr(n, n, [&] { return normal(rng); });
    const MatrixXd W = F.transpose() * F + 0.1 * MatrixXd::Identity(n, n);
    const double mu = 0.5 + std::abs(normal(rng));
    const VectorXd x = VectorXd::Zero(n), free = VectorXd::Constant(n, std::numeric_limits<double>::infinity());
    const VectorXd lower = -free;
    const cyclopt::qp::QpSolution restricted = solve_l1_relaxed_subproblem({e, x, lower, free}, W, mu, {}, {}, {});
    const cyclopt::qp::QpSolution full = cyclopt::qp::solve_active_set(full_relaxed_program(e, W, mu));
    ASSERT_EQ(restricted.status, cyclopt::qp::QpStatus::optimal);
    ASSERT_EQ(full.status, cyclopt::qp::QpStatus::optimal);
    const Penalties penalties = Penalties::uniform(mu, m_eq, m_in);
    EXPECT_NEAR(l1_model(e, W, restricted.x.head(n), penalties), l1_model(e, W, full.x.head(n), penalties), 1e-9)
        << "instance " << k;
    int violated = 0;
    for (int i = 0; i < m_in; ++i) violated += e.inequalities[i] > 0.0;
    grown += restricted.x.size() > n + 2 * m_eq + violated;
  }
  std::printf("l1-relaxed QPs: 200 compared with the full program, %d needed extra slacks\n", grown);
  EXPECT_GT(grown, 0);  // the on-demand path was exercised
}

}  // namespace
