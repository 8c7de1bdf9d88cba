// Ipopt and the seed's SQP on Hock-Schittkowski problems: both reach the published optimum and
// each other's objective (issue 4, acceptance 1), with consistent multipliers; the evaluation-
// failure ("no real solution") rule; an incompatible QP subproblem (l1 relaxation).
#include "hock_schittkowski.hpp"

#include "cyclopt/nlp/kkt_measures.hpp"
#include "cyclopt/nlp/solve.hpp"
#include "cyclopt/nlp/sqp_subproblems.hpp"
#include "cyclopt/qp/active_set_solver.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace {

using namespace cyclopt::nlp;
using cyclopt::nlp::testing::hock_schittkowski_problems;
using cyclopt::nlp::testing::TestProblem;
using cyclopt::nlp::testing::vec;

SolverOptions options_for(SolverKind kind) {
  SolverOptions o;
  o.solver = kind;
  return o;
}

// The KKT conditions checked independently of the solvers' own reports, from a fresh evaluation.
void expect_kkt_point(Problem& p, const SolverSummary& s, double tol) {
  Evaluation e;
  ASSERT_TRUE(p.evaluate(s.x, true, e).ok);
  EXPECT_LE(constraint_violation(e, s.x, p.lower_bounds(), p.upper_bounds()), 1e-8);
  EXPECT_LE(lagrangian_gradient(e, s.equality_multipliers, s.inequality_multipliers, s.bound_multipliers).lpNorm<Eigen::Infinity>(),
            tol);
  if (e.inequalities.size()) {
    EXPECT_GE(s.inequality_multipliers.minCoeff(), -tol);
    EXPECT_LE(s.inequality_multipliers.cwiseProduct(e.inequalities).cwiseAbs().maxCoeff(), tol);
  }
}

class HockSchittkowski : public ::testing::TestWithParam<int> {};

TEST_P(HockSchittkowski, BothSolversReachThePublishedOptimumAndAgree) {
  const TestProblem tp = hock_schittkowski_problems()[static_cast<size_t>(GetParam())];
  SCOPED_TRACE(tp.name);
  auto ipopt_problem = tp.make();
  auto sqp_problem = tp.make();
  const SolverSummary ipopt = solve(*ipopt_problem, options_for(SolverKind::ipopt), tp.x0);
  const SolverSummary sqp = solve(*sqp_problem, options_for(SolverKind::sqp), tp.x0);
  std::printf("%-6s ipopt: %-10s it %3d evals %3d %7.2f ms f %+.12e | sqp: %-10s it %3d evals %3d %7.2f ms f %+.12e | "
              "|df| %.1e\n",
              tp.name.c_str(), to_string(ipopt.termination), ipopt.iterations,
              ipopt.function_evaluations + ipopt.jacobian_evaluations, 1e3 * ipopt.wall_seconds, ipopt.objective,
              to_string(sqp.termination), sqp.iterations, sqp.function_evaluations + sqp.jacobian_evaluations,
              1e3 * sqp.wall_seconds, sqp.objective, std::abs(ipopt.objective - sqp.objective));
  ASSERT_TRUE(ipopt.success()) << ipopt.message;
  ASSERT_TRUE(sqp.success()) << sqp.message;
  const double scale = std::max(1.0, std::abs(tp.f_star));
  EXPECT_NEAR(ipopt.objective, tp.f_star, std::max(1e-8, tp.published_digits_tolerance) * scale);
  EXPECT_NEAR(sqp.objective, tp.f_star, std::max(1e-8, tp.published_digits_tolerance) * scale);
  EXPECT_NEAR(ipopt.objective, sqp.objective, 1e-8 * std::max(1.0, std::abs(sqp.objective)));  // acceptance 1
  const double x_tol = std::max(1e-5, 10 * tp.published_digits_tolerance);
  for (Eigen::Index i = 0; i < tp.x_star.size(); ++i) {
    EXPECT_NEAR(ipopt.x[i], tp.x_star[i], x_tol * (1 + std::abs(tp.x_star[i])));
    EXPECT_NEAR(sqp.x[i], tp.x_star[i], x_tol * (1 + std::abs(tp.x_star[i])));
  }
  expect_kkt_point(*ipopt_problem, ipopt, 1e-6);
  expect_kkt_point(*sqp_problem, sqp, 1e-7);
  // Same multipliers (these problems satisfy LICQ and strict complementarity at the optimum).
  EXPECT_LE((ipopt.equality_multipliers - sqp.equality_multipliers).lpNorm<Eigen::Infinity>(), 1e-4);
  EXPECT_LE((ipopt.inequality_multipliers - sqp.inequality_multipliers).lpNorm<Eigen::Infinity>(), 1e-4);
  EXPECT_LE((ipopt.bound_multipliers - sqp.bound_multipliers).lpNorm<Eigen::Infinity>(), 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Problems, HockSchittkowski,
                         ::testing::Range(0, static_cast<int>(hock_schittkowski_problems().size())),
                         [](const ::testing::TestParamInfo<int>& info) {
                           return hock_schittkowski_problems()[static_cast<size_t>(info.param)].name;
                         });

// min (x1 - 1)^2 + (x2 - 2)^2 s.t. x1 + x2 = 1, with "no real solution" for x1 > 0.25:
// optimum (0, 1), f = 2. From (-3, 4) the first full steps land in the failing region.
struct FailingRegion {
  static constexpr int n = 2, m_eq = 1, m_in = 0;
  static bool evaluable(const double* x) { return x[0] <= 0.25; }
  template <class T> static void evaluate(const T* x, T& f, T* eq, T*) {
    f = (x[0] - 1.0) * (x[0] - 1.0) + (x[1] - 2.0) * (x[1] - 2.0);
    eq[0] = x[0] + x[1] - 1.0;
  }
};

TEST(EvaluationFailure, BothSolversShortenStepsIntoTheFailingRegion) {
  using Problem2 = cyclopt::nlp::testing::AutodiffProblem<FailingRegion>;
  for (SolverKind kind : {SolverKind::ipopt, SolverKind::sqp}) {
    Problem2 problem;
    const SolverSummary s = solve(problem, options_for(kind), vec({-3, 4}));
    std::printf("failing region, %s: %s, %d iterations, %d failed evaluations\n", to_string(kind), to_string(s.termination),
                s.iterations, s.failed_evaluations);
    ASSERT_TRUE(s.success()) << to_string(kind) << ": " << s.message;
    EXPECT_NEAR(s.objective, 2.0, 1e-8);
    EXPECT_NEAR(s.x[0], 0.0, 1e-6);
    if (kind == SolverKind::sqp) {
      EXPECT_GT(s.failed_evaluations, 0);
    }
  }
}

TEST(EvaluationFailure, FailingStartIsReportedNotThrown) {
  using Problem2 = cyclopt::nlp::testing::AutodiffProblem<FailingRegion>;
  for (SolverKind kind : {SolverKind::ipopt, SolverKind::sqp}) {
    Problem2 problem;
    const SolverSummary s = solve(problem, options_for(kind), vec({1, 0}));
    EXPECT_EQ(s.termination, Termination::evaluation_failure) << to_string(kind) << ": " << s.message;
    EXPECT_GT(s.failed_evaluations, 0);
  }
}

// Circle x1^2 + x2^2 = 1 and line x1 + x2 = 1, min (x1 - 1)^2 + x2^2 (feasible set {(1,0), (0,1)}).
// At (2, 2) both gradients are parallel: the linearised constraints are inconsistent.
struct CircleAndLine {
  static constexpr int n = 2, m_eq = 2, m_in = 0;
  template <class T> static void evaluate(const T* x, T& f, T* eq, T*) {
    f = (x[0] - 1.0) * (x[0] - 1.0) + x[1] * x[1];
    eq[0] = x[0] * x[0] + x[1] * x[1] - 1.0;
    eq[1] = x[0] + x[1] - 1.0;
  }
};

TEST(IncompatibleSubproblem, SqpRecoversThroughTheL1Relaxation) {
  using P = cyclopt::nlp::testing::AutodiffProblem<CircleAndLine>;
  P problem;
  const Eigen::VectorXd x0 = vec({2, 2});
  Evaluation e;
  ASSERT_TRUE(problem.evaluate(x0, true, e).ok);
  const Eigen::VectorXd upper = Eigen::VectorXd::Constant(2, cyclopt::nlp::testing::kInf), lower = -upper;
  const auto qp = cyclopt::qp::solve_active_set(sqp_subproblem({e, x0, lower, upper}, Eigen::MatrixXd::Identity(2, 2)));
  ASSERT_EQ(qp.status, cyclopt::qp::QpStatus::infeasible);  // the premise: (6.7) is incompatible at x0
  for (SolverKind kind : {SolverKind::sqp, SolverKind::ipopt}) {
    P p;
    const SolverSummary s = solve(p, options_for(kind), x0);
    ASSERT_TRUE(s.success()) << to_string(kind) << ": " << s.message;
    EXPECT_LE(s.constraint_violation, 1e-8);
    EXPECT_TRUE(std::abs(s.objective) < 1e-8 || std::abs(s.objective - 2.0) < 1e-8) << s.objective;
  }
}

// SqpOptions::max_qp_iterations: the SQP counts its subproblems' active-set iterations and ends at
// max_iterations once they exceed the budget; without a budget the same run converges.
TEST(QpIterationBudget, TheSqpStopsOnceItsSubproblemsHaveTakenTheBudget) {
  using P = cyclopt::nlp::testing::AutodiffProblem<CircleAndLine>;
  SolverOptions o = options_for(SolverKind::sqp);
  P free_run;
  const SolverSummary unlimited = solve(free_run, o, vec({2, 2}));
  ASSERT_TRUE(unlimited.success()) << unlimited.message;
  ASSERT_GE(unlimited.qp_iterations, 2) << "the premise: the run's QPs take more than one active-set iteration";
  o.sqp.max_qp_iterations = 1;
  P budgeted;
  const SolverSummary stopped = solve(budgeted, o, vec({2, 2}));
  EXPECT_EQ(stopped.termination, Termination::max_iterations);
  EXPECT_NE(stopped.message.find("MaxQpIter"), std::string::npos) << stopped.message;
  EXPECT_GT(stopped.qp_iterations, 1);
  EXPECT_LT(stopped.iterations, unlimited.iterations);
  o.sqp.max_qp_iterations = -1;
  P invalid;
  EXPECT_THROW(solve(invalid, o, vec({2, 2})), std::invalid_argument);
}

// Inconsistent constraints x1 >= 1 and x1^2 <= 1/4: the violation max(0, 1 - x1) + max(0, x1^2 - 1/4)
// is stationary at x1 = 1/2, where the SQP stops (Algorithm 1, step 5); Ipopt reports infeasible.
struct Inconsistent {
  static constexpr int n = 2, m_eq = 0, m_in = 2;
  template <class T> static void evaluate(const T* x, T& f, T*, T* in) {
    f = x[0] * x[0] + x[1] * x[1];
    in[0] = 1.0 - x[0];
    in[1] = x[0] * x[0] - 0.25;
  }
};

TEST(Infeasibility, BothSolversReportAnInfeasibleProblem) {
  using P = cyclopt::nlp::testing::AutodiffProblem<Inconsistent>;
  for (SolverKind kind : {SolverKind::sqp, SolverKind::ipopt}) {
    P p;
    const SolverSummary s = solve(p, options_for(kind), vec({2, 1}));
    EXPECT_EQ(s.termination, Termination::infeasible) << to_string(kind) << ": " << s.message;
    if (kind == SolverKind::sqp) {
      EXPECT_NEAR(s.x[0], 0.5, 1e-6);
    }
  }
}

}  // namespace
