// Bound-constrained least squares (bounded_least_squares.hpp): the solutions satisfy the KKT
// conditions of min 1/2 |Ax - b|^2 s.t. lower <= x <= upper, checked directly (gradient sign at each
// bound, zero gradient inside), and match the primal active-set QP solver on the same problem -
// on the shapes the Clarke test builds: few rows, many columns, dependent columns, free and
// one-sided and two-sided boxes.
#include "cyclopt/qp/active_set_solver.hpp"
#include "cyclopt/qp/bounded_least_squares.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <limits>
#include <random>

namespace {

using cyclopt::qp::BoundedLeastSquaresSolution;
using cyclopt::qp::solve_bounded_least_squares;
using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kInf = std::numeric_limits<double>::infinity();

// KKT of min 1/2 |Ax - b|^2 on the box: feasible, and the gradient A'(Ax - b) is >= 0 at a lower
// bound, <= 0 at an upper bound, 0 inside.
void expect_box_kkt(const MatrixXd& A, const VectorXd& b, const VectorXd& lo, const VectorXd& hi,
                    const BoundedLeastSquaresSolution& s, double tol) {
  ASSERT_TRUE(s.converged);
  EXPECT_LE((s.residual - (A * s.x - b)).lpNorm<Eigen::Infinity>(), 1e-12 * (1.0 + b.norm()));
  const VectorXd gradient = A.transpose() * (A * s.x - b);
  for (Eigen::Index j = 0; j < A.cols(); ++j) {
    SCOPED_TRACE("column " + std::to_string(j));
    EXPECT_GE(s.x[j], lo[j]);
    EXPECT_LE(s.x[j], hi[j]);
    const bool at_lower = s.x[j] == lo[j], at_upper = s.x[j] == hi[j];
    if (at_lower && at_upper) continue;
    if (at_lower) EXPECT_GE(gradient[j], -tol);
    else if (at_upper) EXPECT_LE(gradient[j], tol);
    else EXPECT_NEAR(gradient[j], 0.0, tol);
  }
}

TEST(BoundedLeastSquares, UnconstrainedFullRankIsTheLeastSquaresSolution) {
  std::mt19937_64 rng(1);
  std::normal_distribution<double> normal;
  const MatrixXd A = MatrixXd::NullaryExpr(8, 4, [&] { return normal(rng); });
  const VectorXd b = VectorXd::NullaryExpr(8, [&] { return normal(rng); });
  const BoundedLeastSquaresSolution s =
      solve_bounded_least_squares(A, b, VectorXd::Constant(4, -kInf), VectorXd::Constant(4, kInf));
  ASSERT_TRUE(s.converged);
  const VectorXd reference = A.colPivHouseholderQr().solve(b);
  EXPECT_LE((s.x - reference).lpNorm<Eigen::Infinity>(), 1e-12);
}

TEST(BoundedLeastSquares, NonnegativeByHand) {
  // min (x1 - 1)^2 + (x2 + 2)^2, x >= 0: x = (1, 0).
  const MatrixXd A = MatrixXd::Identity(2, 2);
  const VectorXd b = (VectorXd(2) << 1.0, -2.0).finished();
  const BoundedLeastSquaresSolution s = solve_bounded_least_squares(A, b, VectorXd::Zero(2), VectorXd::Constant(2, kInf));
  ASSERT_TRUE(s.converged);
  EXPECT_NEAR(s.x[0], 1.0, 1e-15);
  EXPECT_EQ(s.x[1], 0.0);
}

TEST(BoundedLeastSquares, RandomWideDependentProblemsSatisfyKktAndMatchTheQpSolver) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int k = 0; k < 60; ++k) {
    SCOPED_TRACE("problem " + std::to_string(k));
    const int m = 3 + k % 6, n = 2 + (k * 7) % 25;
    MatrixXd A = MatrixXd::NullaryExpr(m, n, [&] { return normal(rng); });
    for (int j = 1; j < n; j += 4) A.col(j) = (0.5 + uniform(rng)) * A.col(j - 1);  // dependent (parallel) columns
    const VectorXd b = VectorXd::NullaryExpr(m, [&] { return 3.0 * normal(rng); });
    VectorXd lo(n), hi(n);
    for (int j = 0; j < n; ++j) {
      const double r = uniform(rng);
      lo[j] = r < 0.2 ? -kInf : (r < 0.6 ? 0.0 : -uniform(rng));
      hi[j] = r < 0.2 ? kInf : (r < 0.4 ? kInf : lo[j] + 2.0 * uniform(rng));
    }
    const BoundedLeastSquaresSolution s = solve_bounded_least_squares(A, b, lo, hi);
    expect_box_kkt(A, b, lo, hi, s, 1e-9 * (1.0 + b.norm()) * (1.0 + A.norm()));
    // The same minimum as the QP  min 1/2 x'A'Ax - (A'b)'x  on the box (a regularised Hessian keeps
    // the QP solver's semidefinite handling out of the comparison; the optimal values agree to it).
    cyclopt::qp::QuadraticProgram qp;
    qp.hessian = A.transpose() * A + 1e-12 * MatrixXd::Identity(n, n);
    qp.gradient = -A.transpose() * b;
    qp.equality_matrix = MatrixXd(0, n);
    qp.inequality_matrix = MatrixXd(0, n);
    qp.lower_bounds = lo;
    qp.upper_bounds = hi;
    const cyclopt::qp::QpSolution q = cyclopt::qp::solve_active_set(qp);
    ASSERT_EQ(q.status, cyclopt::qp::QpStatus::optimal);
    EXPECT_NEAR(s.residual.squaredNorm(), (A * q.x - b).squaredNorm(), 1e-7 * (1.0 + b.squaredNorm()));
  }
}

TEST(BoundedLeastSquares, BadInputNamesTheArgument) {
  const MatrixXd A = MatrixXd::Identity(2, 2);
  EXPECT_THROW(solve_bounded_least_squares(A, VectorXd::Zero(3), VectorXd::Zero(2), VectorXd::Ones(2)), std::invalid_argument);
  EXPECT_THROW(solve_bounded_least_squares(A, VectorXd::Zero(2), VectorXd::Ones(2), VectorXd::Zero(2)), std::invalid_argument);
}

}  // namespace
