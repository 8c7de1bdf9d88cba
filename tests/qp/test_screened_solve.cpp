// Constraint screening (screened_solve.hpp) returns the full QP's solution: on QPs with many rows
// of which few can be active, like the walker's SQP subproblems (rows as far from active as
// 10 units, clusters of nearly parallel rows as on a fine phase grid).
#include "cyclopt/qp/screened_solve.hpp"
#include "qp_kkt.hpp"
#include "random_qp.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <limits>
#include <random>

namespace {

using cyclopt::qp::QpSolution;
using cyclopt::qp::QpStatus;
using cyclopt::qp::QuadraticProgram;
using cyclopt::qp::ScreeningOptions;
using cyclopt::qp::solve_active_set;
using cyclopt::qp::solve_screened;
using cyclopt::qp::testing::expect_kkt;
using cyclopt::qp::testing::many_row_qp;
using Eigen::MatrixXd;
using Eigen::VectorXd;

TEST(ScreenedSolve, SameSolutionAsTheFullQp) {
  std::mt19937_64 rng(4);
  int screened_iterations = 0, full_iterations = 0;
  for (int k = 0; k < 40; ++k) {
    SCOPED_TRACE("QP " + std::to_string(k));
    const QuadraticProgram qp = many_row_qp(rng, 12, 60);
    const QpSolution full = solve_active_set(qp);
    const QpSolution screened = solve_screened(qp, {}, {}, ScreeningOptions{});
    ASSERT_EQ(full.status, QpStatus::optimal) << full.message;
    expect_kkt(qp, screened, 1e-8 * (1.0 + qp.gradient.lpNorm<Eigen::Infinity>()));
    EXPECT_NEAR(screened.objective, full.objective, 1e-9 * std::max(1.0, std::abs(full.objective)));
    EXPECT_EQ(screened.inequality_multipliers.size(), qp.inequality_rhs.size());
    // Warm-started from its own working set (the SQP's next iteration): still the solution.
    const QpSolution warm = solve_screened(qp, {}, screened.working_set, ScreeningOptions{});
    expect_kkt(qp, warm, 1e-8 * (1.0 + qp.gradient.lpNorm<Eigen::Infinity>()));
    screened_iterations += screened.iterations;
    full_iterations += full.iterations;
  }
  std::printf("screened: %d active-set iterations, full: %d\n", screened_iterations, full_iterations);
}

TEST(ScreenedSolve, RowsScreenedOutButActiveAtTheOptimumAreAdded) {
  // min (x - 5)^2 s.t. x <= 4 (screened out with margin 0.5: rhs 4 > 0.5) and x <= 10.
  QuadraticProgram qp;
  qp.hessian = MatrixXd::Constant(1, 1, 2.0);
  qp.gradient = VectorXd::Constant(1, -10.0);
  qp.equality_matrix = MatrixXd(0, 1);
  qp.inequality_matrix = MatrixXd::Ones(2, 1);
  qp.inequality_rhs = (VectorXd(2) << 4.0, 10.0).finished();
  const QpSolution s = solve_screened(qp, {}, {}, ScreeningOptions{});
  expect_kkt(qp, s, 1e-12);
  EXPECT_NEAR(s.x[0], 4.0, 1e-12);
  EXPECT_NEAR(s.inequality_multipliers[0], 2.0, 1e-12);
  EXPECT_EQ(s.inequality_multipliers[1], 0.0);
  ASSERT_EQ(s.working_set.inequalities.size(), 1u);
  EXPECT_EQ(s.working_set.inequalities[0], 0);
}

TEST(ScreenedSolve, InfeasibleAndUnboundedAsTheFullQp) {
  // Infeasible: x <= -1 (kept) and -x <= -1 (x >= 1, kept).
  QuadraticProgram qp;
  qp.hessian = MatrixXd::Zero(1, 1);
  qp.gradient = VectorXd::Constant(1, -1.0);
  qp.equality_matrix = MatrixXd(0, 1);
  qp.inequality_matrix = (MatrixXd(2, 1) << 1.0, -1.0).finished();
  qp.inequality_rhs = (VectorXd(2) << -1.0, -1.0).finished();
  EXPECT_EQ(solve_screened(qp, {}, {}, ScreeningOptions{}).status, QpStatus::infeasible);
  // An LP bounded only by a screened-out row (x <= 7): optimal at 7, not unbounded.
  qp.inequality_matrix = MatrixXd::Ones(1, 1);
  qp.inequality_rhs = VectorXd::Constant(1, 7.0);
  const QpSolution bounded = solve_screened(qp, {}, {}, ScreeningOptions{});
  ASSERT_EQ(bounded.status, QpStatus::optimal) << bounded.message;
  EXPECT_NEAR(bounded.x[0], 7.0, 1e-12);
  // Truly unbounded: no row bounds x from above.
  qp.inequality_matrix = -MatrixXd::Ones(1, 1);
  EXPECT_EQ(solve_screened(qp, {}, {}, ScreeningOptions{}).status, QpStatus::unbounded);
}

}  // namespace
