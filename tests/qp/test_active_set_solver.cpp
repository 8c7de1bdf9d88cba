// Active-set QP solver against QPs with analytic solutions (incl. degenerate, infeasible,
// semidefinite and unbounded ones) and KKT checks on randomized QPs.
#include "cyclopt/qp/active_set_solver.hpp"
#include "cyclopt/qp/dual_active_set_solver.hpp"
#include "qp_kkt.hpp"
#include "random_qp.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

namespace {

using cyclopt::qp::ActiveSetOptions;
using cyclopt::qp::QpSolution;
using cyclopt::qp::QpStatus;
using cyclopt::qp::QuadraticProgram;
using cyclopt::qp::solve_active_set;
using cyclopt::qp::solve_dual_active_set;
using cyclopt::qp::testing::expect_kkt;
using cyclopt::qp::testing::random_qp;
using cyclopt::qp::testing::unconstrained;
using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Nocedal & Wright, Example 16.4: solution (1.4, 1.7), only the first constraint active (y = 0.8).
QuadraticProgram nocedal_wright_example_16_4() {
  QuadraticProgram qp = unconstrained(2.0 * MatrixXd::Identity(2, 2), VectorXd((VectorXd(2) << -2, -5).finished()));
  qp.inequality_matrix = (MatrixXd(3, 2) << -1, 2, 1, 2, 1, -2).finished();
  qp.inequality_rhs = (VectorXd(3) << 2, 6, 2).finished();
  qp.lower_bounds = VectorXd::Zero(2);
  return qp;
}

TEST(ActiveSetSolver, EqualityConstrainedLeastNorm) {
  const int n = 5;
  QuadraticProgram qp = unconstrained(MatrixXd::Identity(n, n), VectorXd::Zero(n));
  qp.equality_matrix = MatrixXd::Ones(1, n);
  qp.equality_rhs = VectorXd::Ones(1);
  const QpSolution s = solve_active_set(qp);
  expect_kkt(qp, s, 1e-12);
  EXPECT_LE((s.x - VectorXd::Constant(n, 1.0 / n)).norm(), 1e-12);
  EXPECT_NEAR(s.equality_multipliers[0], -1.0 / n, 1e-12);
}

// Strictly convex cases with known solutions, for the primal method and the Goldfarb-Idnani dual
// method (dual_active_set_solver.hpp) alike.
using Solver = QpSolution (*)(const QuadraticProgram&, const ActiveSetOptions&);
QpSolution primal(const QuadraticProgram& qp, const ActiveSetOptions& o) { return solve_active_set(qp, o); }

class StrictlyConvexCases : public ::testing::TestWithParam<Solver> {};

TEST_P(StrictlyConvexCases, NocedalWrightExample16_4) {
  const QuadraticProgram qp = nocedal_wright_example_16_4();
  const QpSolution s = GetParam()(qp, {});
  expect_kkt(qp, s, 1e-12);
  EXPECT_NEAR(s.x[0], 1.4, 1e-12);
  EXPECT_NEAR(s.x[1], 1.7, 1e-12);
  EXPECT_NEAR(s.inequality_multipliers[0], 0.8, 1e-12);
  EXPECT_EQ(s.working_set.inequalities, std::vector<int>{0});
}

// Degenerate vertex: four constraints active at the origin in 2-D (two bounds, two redundant rows).
TEST_P(StrictlyConvexCases, DegenerateVertexWithRedundantActiveConstraints) {
  QuadraticProgram qp = unconstrained(2.0 * MatrixXd::Identity(2, 2), VectorXd::Constant(2, 2.0));  // (x+1)^2
  qp.inequality_matrix = (MatrixXd(3, 2) << -1, -1, -1, -2, -2, -2).finished();
  qp.inequality_rhs = VectorXd::Zero(3);
  qp.lower_bounds = VectorXd::Zero(2);
  const QpSolution s = GetParam()(qp, {});
  expect_kkt(qp, s, 1e-12);
  EXPECT_LE(s.x.norm(), 1e-12);
  EXPECT_LE(s.working_set.inequalities.size() + s.working_set.lower_bounds.size(), 2u);
}

TEST_P(StrictlyConvexCases, RedundantEqualities) {
  QuadraticProgram qp = unconstrained(MatrixXd::Identity(2, 2), VectorXd::Zero(2));
  qp.equality_matrix = (MatrixXd(3, 2) << 1, 1, 2, 2, -1, -1).finished();
  qp.equality_rhs = (VectorXd(3) << 1, 2, -1).finished();
  const QpSolution s = GetParam()(qp, {});
  expect_kkt(qp, s, 1e-12);
  EXPECT_NEAR(s.x[0], 0.5, 1e-12);
  EXPECT_NEAR(s.x[1], 0.5, 1e-12);
  qp.equality_rhs[1] = 3.0;  // now contradictory
  EXPECT_EQ(GetParam()(qp, {}).status, QpStatus::infeasible);
}

INSTANTIATE_TEST_SUITE_P(PrimalAndDual, StrictlyConvexCases, ::testing::Values(&primal, &solve_dual_active_set));

TEST(ActiveSetSolver, InfeasibleInequalitiesAndBounds) {
  QuadraticProgram qp = unconstrained(MatrixXd::Identity(2, 2), VectorXd::Zero(2));
  qp.inequality_matrix = MatrixXd::Ones(1, 2);
  qp.inequality_rhs = VectorXd::Constant(1, -1.0);  // x1 + x2 <= -1 ...
  qp.lower_bounds = VectorXd::Zero(2);              // ... with x >= 0
  const QpSolution s = solve_active_set(qp);
  EXPECT_EQ(s.status, QpStatus::infeasible);
  EXPECT_NE(s.message.find("inconsistent"), std::string::npos);
  // Contradictory bounds through general rows: x1 <= 0 and x1 >= 1.
  qp.inequality_matrix = (MatrixXd(2, 2) << 1, 0, -1, 0).finished();
  qp.inequality_rhs = (VectorXd(2) << 0, -1).finished();
  qp.lower_bounds.resize(0);
  EXPECT_EQ(solve_active_set(qp).status, QpStatus::infeasible);
}

TEST(ActiveSetSolver, SemidefiniteHessianBoundedByConstraint) {
  // min 1/2 x1^2 - x2 s.t. x2 <= 3: zero curvature in x2, optimum (0, 3), multiplier 1.
  QuadraticProgram qp = unconstrained((MatrixXd(2, 2) << 1, 0, 0, 0).finished(), (VectorXd(2) << 0.5, -1).finished());
  qp.upper_bounds = (VectorXd(2) << kInf, 3).finished();
  const QpSolution s = solve_active_set(qp);
  expect_kkt(qp, s, 1e-12);
  EXPECT_NEAR(s.x[0], -0.5, 1e-12);
  EXPECT_NEAR(s.x[1], 3.0, 1e-12);
  EXPECT_NEAR(s.upper_bound_multipliers[1], 1.0, 1e-12);
}

TEST(ActiveSetSolver, SemidefiniteUnboundedAndLinearProgramUnbounded) {
  QuadraticProgram qp = unconstrained((MatrixXd(2, 2) << 1, 0, 0, 0).finished(), (VectorXd(2) << 0, 1).finished());
  EXPECT_EQ(solve_active_set(qp).status, QpStatus::unbounded);
  QuadraticProgram lp = unconstrained(MatrixXd::Zero(2, 2), (VectorXd(2) << -1, 0).finished());
  lp.lower_bounds = VectorXd::Zero(2);
  lp.inequality_matrix = (MatrixXd(1, 2) << 1, -1).finished();  // x1 <= x2 + 1: unbounded along (1, 1)
  lp.inequality_rhs = VectorXd::Ones(1);
  EXPECT_EQ(solve_active_set(lp).status, QpStatus::unbounded);
}

TEST(ActiveSetSolver, LinearProgramWithNonUniqueOptimum) {
  // min -x1 - x2 s.t. x1 + x2 <= 1, x >= 0: optimal value -1 on a whole edge.
  QuadraticProgram lp = unconstrained(MatrixXd::Zero(2, 2), VectorXd::Constant(2, -1.0));
  lp.inequality_matrix = MatrixXd::Ones(1, 2);
  lp.inequality_rhs = VectorXd::Ones(1);
  lp.lower_bounds = VectorXd::Zero(2);
  const QpSolution s = solve_active_set(lp);
  expect_kkt(lp, s, 1e-12);
  EXPECT_NEAR(s.objective, -1.0, 1e-12);
}

// The shape of the l1-relaxed SQP subproblem (seed 001 eq. (6.13)) in one variable:
// min 1/2 d^2 + mu (r + s) s.t. d - 1 = r - s, r, s >= 0, i.e. min 1/2 d^2 + mu |d - 1|: d = mu.
TEST(ActiveSetSolver, L1RelaxedSubproblemWithZeroCurvatureSlacks) {
  const double mu = 0.5;
  QuadraticProgram qp = unconstrained((MatrixXd(3, 3) << 1, 0, 0, 0, 0, 0, 0, 0, 0).finished(), (VectorXd(3) << 0, mu, mu).finished());
  qp.equality_matrix = (MatrixXd(1, 3) << 1, -1, 1).finished();
  qp.equality_rhs = VectorXd::Ones(1);
  qp.lower_bounds = (VectorXd(3) << -kInf, 0, 0).finished();
  const QpSolution s = solve_active_set(qp);
  expect_kkt(qp, s, 1e-12);
  EXPECT_NEAR(s.x[0], mu, 1e-12);
  EXPECT_NEAR(s.objective, 0.5 * mu * mu + mu * (1 - mu), 1e-12);
}

TEST(ActiveSetSolver, RejectsBadInputNamingTheField) {
  QuadraticProgram qp = unconstrained(MatrixXd::Identity(2, 2), VectorXd::Zero(3));
  try {
    solve_active_set(qp);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("hessian"), std::string::npos);
  }
  qp = unconstrained(MatrixXd::Identity(2, 2), VectorXd::Zero(2));
  qp.lower_bounds = VectorXd::Ones(2);
  qp.upper_bounds = VectorXd::Zero(2);
  EXPECT_THROW(solve_active_set(qp), std::invalid_argument);
  ActiveSetOptions bad;
  bad.feasibility_tolerance = 0;
  EXPECT_THROW(solve_active_set(unconstrained(MatrixXd::Identity(2, 2), VectorXd::Zero(2)), bad), std::invalid_argument);
  cyclopt::qp::WorkingSet ws;
  ws.inequalities = {3};
  EXPECT_THROW(solve_active_set(unconstrained(MatrixXd::Identity(2, 2), VectorXd::Zero(2)), {}, ws), std::invalid_argument);
}

TEST(ActiveSetSolver, RandomQpsSatisfyKktConditions) {
  std::mt19937_64 rng(20260601);
  const int count = 600;
  int semidefinite_count = 0, total_iterations = 0, warm_iterations = 0;
  for (int k = 0; k < count; ++k) {
    bool semidefinite = false;
    QuadraticProgram qp = random_qp(rng, &semidefinite);
    semidefinite_count += semidefinite;
    const QpSolution cold = solve_active_set(qp);
    SCOPED_TRACE("random QP " + std::to_string(k));
    const double scale = 1.0 + qp.gradient.lpNorm<Eigen::Infinity>() + qp.hessian.lpNorm<Eigen::Infinity>();
    expect_kkt(qp, cold, 1e-8 * scale);
    total_iterations += cold.iterations;
    // Warm start on a perturbed gradient (the SQP's situation): still a KKT point.
    qp.gradient += 0.01 * VectorXd::NullaryExpr(qp.gradient.size(), [&] { return std::normal_distribution<double>()(rng); });
    const QpSolution warm = solve_active_set(qp, {}, cold.working_set);
    expect_kkt(qp, warm, 1e-8 * scale);
    warm_iterations += warm.iterations;
  }
  std::printf("random QPs: %d (%d semidefinite), cold iterations %d, warm-started iterations %d\n", count, semidefinite_count,
              total_iterations, warm_iterations);
  EXPECT_LT(warm_iterations, total_iterations);
}

TEST(ActiveSetSolver, RandomInfeasibleQpsAreDetected) {
  std::mt19937_64 rng(7);
  for (int k = 0; k < 200; ++k) {
    bool semidefinite = false;
    QuadraticProgram qp = random_qp(rng, &semidefinite);
    // Append a row a'x <= b and its contradiction -a'x <= -b - 1.
    const Eigen::Index n = qp.num_variables(), m = qp.inequality_matrix.rows();
    const VectorXd a = VectorXd::Random(n) + VectorXd::Constant(n, 2.0);
    qp.inequality_matrix.conservativeResize(m + 2, n);
    qp.inequality_rhs.conservativeResize(m + 2);
    qp.inequality_matrix.row(m) = a.transpose();
    qp.inequality_matrix.row(m + 1) = -a.transpose();
    qp.inequality_rhs[m] = 0.0;
    qp.inequality_rhs[m + 1] = -1.0;
    EXPECT_EQ(solve_active_set(qp).status, QpStatus::infeasible) << "random QP " << k;
  }
}

// A consistent equality whose warm-started subspace minimiser is long: 30 variables with Hessian
// curvatures 1 down to 1e-8, an equality row of entries up to 350 (the walker's elastic
// subproblems met |x| ~ 1e6 with such rows), a warm bound on a 31st variable. E x = e then holds
// only to the rounding of E x (~1e-7 at |x| ~ 2e7), and the start must not call it inconsistent.
TEST(ActiveSetSolver, LongWarmStartStepOnAConsistentEqualityIsNotInfeasible) {
  for (int seed = 0; seed < 10; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int n = 31;
    VectorXd h(n), g(n);
    for (int i = 0; i + 1 < n; ++i) {
      h[i] = std::pow(10.0, -8.0 * i / (n - 2));
      g[i] = u(rng);
    }
    h[n - 1] = 1.0;
    g[n - 1] = 0.0;
    QuadraticProgram qp = unconstrained(h.asDiagonal(), g);
    qp.equality_matrix = MatrixXd::Zero(1, n);
    for (int i = 0; i + 1 < n; ++i) qp.equality_matrix(0, i) = 350.0 * u(rng);
    qp.equality_rhs = VectorXd::Constant(1, 4.0);
    qp.lower_bounds = VectorXd::Constant(n, -kInf);
    qp.lower_bounds[n - 1] = 0.0;
    cyclopt::qp::WorkingSet warm;
    warm.lower_bounds = {n - 1};
    const QpSolution s = solve_active_set(qp, {}, warm);
    ASSERT_EQ(s.status, QpStatus::optimal) << "seed " << seed << ": " << s.message;
    const double scale = qp.equality_matrix.cwiseAbs().sum() * s.x.lpNorm<Eigen::Infinity>();
    EXPECT_GT(s.x.lpNorm<Eigen::Infinity>(), 1e6) << seed;
    EXPECT_LE(std::abs(qp.equality_matrix.row(0).dot(s.x) - 4.0), 1e-13 * scale) << seed;
    const VectorXd stationarity = qp.hessian * s.x + qp.gradient + qp.equality_matrix.transpose() * s.equality_multipliers -
                                  s.lower_bound_multipliers;
    EXPECT_LE(stationarity.lpNorm<Eigen::Infinity>(), 1e-8 * std::max(1.0, s.equality_multipliers.cwiseAbs().maxCoeff()))
        << seed;
  }
}

TEST(ActiveSetSolver, WarmStartFromOwnSolutionNeedsNoWork) {
  const QuadraticProgram qp = nocedal_wright_example_16_4();
  const QpSolution cold = solve_active_set(qp);
  const QpSolution warm = solve_active_set(qp, {}, cold.working_set);
  expect_kkt(qp, warm, 1e-12);
  EXPECT_LE(warm.iterations, 1);
  EXPECT_LT(warm.iterations, cold.iterations);
}

}  // namespace
