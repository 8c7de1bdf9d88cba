// Goldfarb-Idnani dual active-set solver (dual_active_set_solver.hpp): the same solutions as the
// primal active-set solver on random and walker-like many-row strictly convex QPs, infeasibility
// detection, and the dispatch of solve_convex. The small cases with known solutions (degenerate
// vertex, redundant equalities) run for both solvers in test_active_set_solver.cpp.
#include "cyclopt/qp/convex_solve.hpp"
#include "cyclopt/qp/dual_active_set_solver.hpp"
#include "qp_kkt.hpp"
#include "random_qp.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <chrono>
#include <cstdio>
#include <random>

namespace {

using cyclopt::qp::is_strictly_convex;
using cyclopt::qp::QpSolution;
using cyclopt::qp::QpStatus;
using cyclopt::qp::QuadraticProgram;
using cyclopt::qp::solve_active_set;
using cyclopt::qp::solve_convex;
using cyclopt::qp::solve_dual_active_set;
using cyclopt::qp::solve_screened;
using cyclopt::qp::testing::expect_kkt;
using cyclopt::qp::testing::many_row_qp;
using cyclopt::qp::testing::random_qp;
using cyclopt::qp::testing::unconstrained;
using Eigen::MatrixXd;
using Eigen::VectorXd;

TEST(DualActiveSetSolver, RejectsSemidefiniteHessianAndSolveConvexFallsBack) {
  // min 1/2 x1^2 - x2 s.t. x2 <= 3: zero curvature in x2.
  QuadraticProgram qp = unconstrained((MatrixXd(2, 2) << 1, 0, 0, 0).finished(), (VectorXd(2) << 0.5, -1).finished());
  qp.upper_bounds = (VectorXd(2) << std::numeric_limits<double>::infinity(), 3).finished();
  EXPECT_FALSE(is_strictly_convex(qp.hessian, 1e-10));
  EXPECT_THROW(solve_dual_active_set(qp), std::invalid_argument);
  const QpSolution s = solve_convex(qp, {}, {}, {});
  expect_kkt(qp, s, 1e-12);
  EXPECT_NEAR(s.x[1], 3.0, 1e-12);
}

// Strictly convex random QPs (those of random_qp with full-rank H): same optimum as the primal
// method; infeasible ones (a row and its contradiction appended) detected.
TEST(DualActiveSetSolver, RandomQpsAgreeWithThePrimalMethod) {
  std::mt19937_64 rng(20261201);
  int solved = 0, infeasible = 0, dual_iterations = 0, primal_iterations = 0;
  while (solved < 400) {
    bool semidefinite = false;
    QuadraticProgram qp = random_qp(rng, &semidefinite);
    if (semidefinite || !is_strictly_convex(qp.hessian, 1e-10)) continue;
    SCOPED_TRACE("random QP " + std::to_string(solved));
    const QpSolution dual = solve_dual_active_set(qp), primal = solve_active_set(qp);
    const double scale = 1.0 + qp.gradient.lpNorm<Eigen::Infinity>() + qp.hessian.lpNorm<Eigen::Infinity>();
    expect_kkt(qp, dual, 1e-8 * scale);
    ASSERT_EQ(primal.status, QpStatus::optimal);
    EXPECT_LE((dual.x - primal.x).norm(), 1e-7 * (1.0 + primal.x.norm()));
    dual_iterations += dual.iterations, primal_iterations += primal.iterations, ++solved;
    const Eigen::Index n = qp.num_variables(), m = qp.inequality_matrix.rows();
    const VectorXd a = VectorXd::Random(n) + VectorXd::Constant(n, 2.0);
    qp.inequality_matrix.conservativeResize(m + 2, n);
    qp.inequality_rhs.conservativeResize(m + 2);
    qp.inequality_matrix.row(m) = a.transpose();
    qp.inequality_matrix.row(m + 1) = -a.transpose();
    qp.inequality_rhs[m] = 0.0;
    qp.inequality_rhs[m + 1] = -1.0;
    infeasible += solve_dual_active_set(qp).status == QpStatus::infeasible;
  }
  EXPECT_EQ(infeasible, solved);
  std::printf("strictly convex random QPs: %d, dual iterations %d, primal iterations %d\n", solved, dual_iterations,
              primal_iterations);
}

// Ill-conditioned H, as the SQP's W_1 from (6.24) with eigenvalues clamped at sqrt(eps) lambda_max
// (cond ~1e8): the working rows must hold to rounding, not to cond(H) eps. The null-space steps
// of the method drift off the working rows by ~cond(H) eps |x|; a SQP whose QP steps leave the
// linearised constraints violated by that much cannot push its violation below it (HS71 with a
// difference-Hessian start crawled at violation 3e-7 with steps of 1e-10 for 500 iterations).
TEST(DualActiveSetSolver, WorkingRowsHoldToRoundingWhenTheHessianIsIllConditioned) {
  std::mt19937_64 rng(71);
  double worst = 0.0;
  for (int k = 0; k < 200; ++k) {
    const QuadraticProgram qp = cyclopt::qp::testing::ill_conditioned_qp(rng, 4 + k % 8);
    const QpSolution s = solve_dual_active_set(qp);
    ASSERT_EQ(s.status, QpStatus::optimal) << k;
    double residual = std::abs((qp.equality_matrix * s.x - qp.equality_rhs)[0]);
    for (int i : s.working_set.inequalities)
      residual = std::max(residual, std::abs(qp.inequality_matrix.row(i).dot(s.x) - qp.inequality_rhs[i]));
    worst = std::max(worst, residual / (1.0 + s.x.lpNorm<Eigen::Infinity>()));
  }
  std::printf("ill-conditioned QPs: largest working-row residual %.1e relative to |x|\n", worst);
  EXPECT_LE(worst, 1e-13);
}

// Walker-like QPs (1200 rows in clusters of nearly parallel rows, 30 variables): the screened
// primal solution, and the time of both.
TEST(DualActiveSetSolver, ManyRowQpsMatchTheScreenedPrimalSolution) {
  std::mt19937_64 rng(5);
  double dual_seconds = 0.0, primal_seconds = 0.0;
  for (int k = 0; k < 20; ++k) {
    SCOPED_TRACE("QP " + std::to_string(k));
    const QuadraticProgram qp = many_row_qp(rng, 30, 120);
    const auto t0 = std::chrono::steady_clock::now();
    const QpSolution dual = solve_dual_active_set(qp);
    const auto t1 = std::chrono::steady_clock::now();
    const QpSolution primal = solve_screened(qp, {}, {}, {});
    const auto t2 = std::chrono::steady_clock::now();
    dual_seconds += std::chrono::duration<double>(t1 - t0).count();
    primal_seconds += std::chrono::duration<double>(t2 - t1).count();
    expect_kkt(qp, dual, 1e-8 * (1.0 + qp.gradient.lpNorm<Eigen::Infinity>()));
    ASSERT_EQ(primal.status, QpStatus::optimal);
    EXPECT_NEAR(dual.objective, primal.objective, 1e-9 * std::max(1.0, std::abs(primal.objective)));
  }
  std::printf("many-row QPs (30 variables, 1200 rows): dual %.2f ms, screened primal %.2f ms per QP\n", dual_seconds * 1e3 / 20,
              primal_seconds * 1e3 / 20);
}

}  // namespace
