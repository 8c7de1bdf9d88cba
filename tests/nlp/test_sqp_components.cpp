// The building blocks of the seed's SQP, each against an independent property.
#include "cyclopt/nlp/active_set_projections.hpp"
#include "cyclopt/nlp/damped_bfgs.hpp"
#include "cyclopt/nlp/l1_merit.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

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
