// The solve() entry point, option parsing/validation and the iteration callback.
#include "autodiff_problem.hpp"
#include "hock_schittkowski.hpp"

#include "cyclopt/nlp/difference_hessian.hpp"
#include "cyclopt/nlp/solve.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <utility>
#include <vector>

namespace {

using namespace cyclopt::nlp;
using cyclopt::nlp::testing::hock_schittkowski_problems;
using cyclopt::nlp::testing::TestProblem;
using cyclopt::nlp::testing::vec;

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SolverKind, ParsesAndRejectsWithFieldAndAllowedValues) {
  EXPECT_EQ(parse_solver_kind("ipopt"), SolverKind::ipopt);
  EXPECT_EQ(parse_solver_kind("sqp"), SolverKind::sqp);
  EXPECT_STREQ(to_string(SolverKind::sqp), "sqp");
  const std::string m = message_of([] { parse_solver_kind("fmincon", "spec.solver"); });
  EXPECT_NE(m.find("spec.solver"), std::string::npos);
  EXPECT_NE(m.find("ipopt, sqp"), std::string::npos);
}

TEST(SolverOptions, ValidationNamesTheField) {
  auto problem = hock_schittkowski_problems()[2].make();
  SolverOptions o;
  o.optimality_tolerance = -1;
  EXPECT_NE(message_of([&] { solve(*problem, o, vec({-1.2, 1})); }).find("optimality_tolerance"), std::string::npos);
  o = {};
  o.solver = SolverKind::sqp;
  o.sqp.epsilon2 = 0.5;  // must be <= epsilon1 = 0.1
  EXPECT_NE(message_of([&] { solve(*problem, o, vec({-1.2, 1})); }).find("sqp.epsilon2"), std::string::npos);
  o = {};
  o.sqp.difference_hessian_every = -1;
  EXPECT_NE(message_of([&] { solve(*problem, o, vec({-1.2, 1})); }).find("sqp.difference_hessian_every"), std::string::npos);
  o = {};
  o.ipopt.difference_hessian_every = -1;
  EXPECT_NE(message_of([&] { solve(*problem, o, vec({-1.2, 1})); }).find("ipopt.difference_hessian_every"), std::string::npos);
  o = {};
  o.sqp.progress_window = -1;
  EXPECT_NE(message_of([&] { solve(*problem, o, vec({-1.2, 1})); }).find("sqp.progress_window"), std::string::npos);
  o = {};
  o.sqp.progress_min_decrease = 1.0;
  EXPECT_NE(message_of([&] { solve(*problem, o, vec({-1.2, 1})); }).find("sqp.progress_min_decrease"), std::string::npos);
  o = {};
  o.ipopt.mu_strategy = "probing";
  EXPECT_NE(message_of([&] { solve(*problem, o, vec({-1.2, 1})); }).find("ipopt.mu_strategy"), std::string::npos);
  EXPECT_NE(message_of([&] { solve(*problem, SolverOptions{}, vec({1, 2, 3})); }).find("x0"), std::string::npos);
}

TEST(SolverOptions, SeedTable62Defaults) {
  const SolverOptions o = seed_table_6_2_options();
  EXPECT_EQ(o.solver, SolverKind::sqp);
  EXPECT_EQ(o.optimality_tolerance, 1e-5);
  EXPECT_EQ(o.constraint_tolerance, 1e-10);
  EXPECT_EQ(o.max_iterations, 2000);
  EXPECT_EQ(o.sqp.backtracking, 0.7);
  EXPECT_EQ(o.sqp.relative_min_penalty, 1e-3);
  EXPECT_EQ(o.sqp.max_function_evaluations, 10000);
  EXPECT_NO_THROW(validate(o));
}

TEST(IterationCallback, ReportsEveryIterationAndStopsOnFalse) {
  for (SolverKind kind : {SolverKind::ipopt, SolverKind::sqp}) {
    auto problem = hock_schittkowski_problems()[13].make();  // HS100
    SolverOptions o;
    o.solver = kind;
    int calls = 0;
    o.on_iteration = [&](const IterationReport& r) {
      EXPECT_GE(r.wall_seconds, 0.0);
      return ++calls < 3;
    };
    const SolverSummary s = solve(*problem, o, vec({1, 2, 0, 4, 0, 1, 1}));
    EXPECT_EQ(s.termination, Termination::user_stop) << to_string(kind);
    EXPECT_EQ(calls, 3) << to_string(kind);
  }
}

TEST(IterationLimit, IsReportedAsMaxIterations) {
  for (SolverKind kind : {SolverKind::ipopt, SolverKind::sqp}) {
    auto problem = hock_schittkowski_problems()[13].make();
    SolverOptions o;
    o.solver = kind;
    o.max_iterations = 2;
    const SolverSummary s = solve(*problem, o, vec({1, 2, 0, 4, 0, 1, 1}));
    EXPECT_EQ(s.termination, Termination::max_iterations) << to_string(kind);
    EXPECT_LE(s.iterations, 2);
  }
}

TEST(SqpInitialHessian, CallerSuppliedLagrangianHessianIsUsed) {
  // HS6: f = (1 - x1)^2, c = 10 (x2 - x1^2): Hessian of the Lagrangian diag(2 - 20 y, 0).
  auto problem = hock_schittkowski_problems()[2].make();
  SolverOptions o;
  o.solver = SolverKind::sqp;
  int calls = 0;
  o.sqp.lagrangian_hessian = [&](const Eigen::VectorXd&, const Eigen::VectorXd& y_eq, const Eigen::VectorXd&) {
    ++calls;
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(2, 2);
    H(0, 0) = 2.0 - 20.0 * y_eq[0];
    return H;
  };
  const SolverSummary s = solve(*problem, o, vec({-1.2, 1}));
  ASSERT_TRUE(s.success()) << s.message;
  EXPECT_EQ(calls, 1);
  EXPECT_NEAR(s.objective, 0.0, 1e-10);
}

TEST(SqpInitialHessian, DifferenceHessianMatchesTheAnalyticOne) {
  // HS6 as above: Hessian of the Lagrangian diag(2 - 20 y, 0) everywhere.
  auto problem = hock_schittkowski_problems()[2].make();
  SolverSummary counts;
  CachedEvaluator evaluator(*problem, counts);
  const Eigen::VectorXd x = vec({-1.2, 1}), y = vec({0.3});
  ASSERT_TRUE(evaluator.evaluate(x, true).ok);
  const Evaluation at = evaluator.evaluation();
  const std::optional<Eigen::MatrixXd> H = lagrangian_hessian_by_differences(evaluator, x, at, y, Eigen::VectorXd());
  ASSERT_TRUE(H.has_value());
  EXPECT_NEAR((*H)(0, 0), 2.0 - 20.0 * 0.3, 1e-6);
  EXPECT_NEAR((*H)(0, 1), 0.0, 1e-6);
  EXPECT_NEAR((*H)(1, 1), 0.0, 1e-6);
  EXPECT_EQ(counts.jacobian_evaluations, 1 + 2);  // x and one forward point per variable
}

TEST(IpoptOptionPassthrough, SetsIpoptOptionsAndRejectsUnknownNames) {
  auto problem = hock_schittkowski_problems()[11].make();  // HS71
  SolverOptions o;
  o.solver = SolverKind::ipopt;
  o.ipopt.integer_options["max_iter"] = 3;  // overrides SolverOptions::max_iterations
  EXPECT_EQ(solve(*problem, o, vec({1, 5, 5, 1})).termination, Termination::max_iterations);
  o.ipopt.numeric_options["no_such_option"] = 1.0;
  EXPECT_THROW(solve(*problem, o, vec({1, 5, 5, 1})), std::invalid_argument);
}

TEST(IpoptDifferenceHessian, ReachesThePublishedOptimaInFewerIterationsThanLimitedMemory) {
  int difference_iterations = 0, limited_memory_iterations = 0;
  for (const TestProblem& tp : hock_schittkowski_problems()) {
    auto problem = tp.make();
    SolverOptions o;
    o.solver = SolverKind::ipopt;
    o.ipopt.hessian = cyclopt::nlp::IpoptHessian::limited_memory;
    const SolverSummary limited_memory = solve(*problem, o, tp.x0);
    o.ipopt.hessian = cyclopt::nlp::IpoptHessian::difference;
    const SolverSummary s = solve(*problem, o, tp.x0);
    ASSERT_TRUE(s.success()) << tp.name << ": " << s.message;
    EXPECT_NEAR(s.objective, tp.f_star, 1e-6 * std::max(1.0, std::abs(tp.f_star))) << tp.name;
    difference_iterations += s.iterations;
    limited_memory_iterations += limited_memory.iterations;
  }
  EXPECT_LT(difference_iterations, limited_memory_iterations);
}

TEST(SqpInitialHessian, DifferenceHessianStartReachesThePublishedOptima) {
  // Not HS39: its Lagrangian Hessian is indefinite at the start, the clamp (6.24) leaves
  // curvature sqrt(eps) lambda_max in those directions and the first steps diverge.
  for (const TestProblem& tp : hock_schittkowski_problems()) {
    if (tp.name == "HS39") continue;
    auto problem = tp.make();
    SolverOptions o;
    o.solver = SolverKind::sqp;
    o.sqp.difference_hessian = true;
    const SolverSummary s = solve(*problem, o, tp.x0);
    ASSERT_TRUE(s.success()) << tp.name << ": " << s.message;
    EXPECT_NEAR(s.objective, tp.f_star, 1e-6 * std::max(1.0, std::abs(tp.f_star))) << tp.name;
    // W_1 is computed after the KKT test of step 2: a restart at the optimum (a continuation's
    // first point is another solve's KKT point) spends no n Jacobians on it.
    const SolverSummary again = solve(*problem, o, s.x);
    ASSERT_TRUE(again.success()) << tp.name << ": " << again.message;
    if (again.iterations == 0) {
      EXPECT_LE(again.jacobian_evaluations, 1) << tp.name;
    } else {
      EXPECT_GE(again.jacobian_evaluations, problem->num_variables()) << tp.name << ": W_1 from differences expected";
    }
  }
}

// The refresh of distant-start solves (walker/distant_start_solver.hpp) every 3 iterations: the
// same optima, and the Jacobians it costs (n per refresh) are spent.
TEST(SqpInitialHessian, DifferenceHessianRefreshReachesThePublishedOptima) {
  for (const TestProblem& tp : hock_schittkowski_problems()) {
    if (tp.name == "HS39") continue;  // see above
    for (SolverKind kind : {SolverKind::sqp, SolverKind::ipopt}) {
      auto problem = tp.make();
      SolverOptions o;
      o.solver = kind;
      o.sqp.difference_hessian = o.ipopt.difference_hessian_start = true;
      const SolverSummary once = solve(*problem, o, tp.x0);
      o.sqp.difference_hessian_every = o.ipopt.difference_hessian_every = 3;
      const SolverSummary s = solve(*problem, o, tp.x0);
      ASSERT_TRUE(s.success()) << tp.name << " " << to_string(kind) << ": " << s.message;
      EXPECT_NEAR(s.objective, tp.f_star, 1e-6 * std::max(1.0, std::abs(tp.f_star))) << tp.name << " " << to_string(kind);
      if (once.iterations > 4 && s.iterations > 4) {
        EXPECT_GE(s.jacobian_evaluations, once.jacobian_evaluations * s.iterations / once.iterations + problem->num_variables())
            << tp.name << " " << to_string(kind) << ": no refresh seen";
      }
    }
  }
}

// min 100 + |x|: the gradient is +-1 everywhere but at the minimiser, so no iterate is a KKT point
// and the SQP creeps towards x = 0 with ever smaller steps, as the distant-start runs of f_mech do
// along its kinks.
struct KinkAtTheMinimum {
  static constexpr int n = 1, m_eq = 0, m_in = 0;
  template <class T>
  static void evaluate(const T* x, T& f, T*, T*) {
    using std::abs;
    f = 100.0 + abs(x[0]);
  }
};

// SqpOptions::progress_window ends such a run as `stalled` once the objective has fallen by less than
// progress_min_decrease relative over the window; runs that converge are not touched.
TEST(SqpProgressWindow, EndsARunWithoutProgressAndSparesConvergingRuns) {
  SolverOptions o = seed_table_6_2_options();
  cyclopt::nlp::testing::AutodiffProblem<KinkAtTheMinimum> kink;
  const SolverSummary creeping = solve(kink, o, vec({0.3}));
  EXPECT_NE(creeping.termination, Termination::stalled) << creeping.message;
  EXPECT_GT(creeping.iterations, 8) << creeping.message;
  o.sqp.progress_window = 5;
  const SolverSummary s = solve(kink, o, vec({0.3}));
  EXPECT_EQ(s.termination, Termination::stalled) << s.message;
  EXPECT_FALSE(s.success());
  EXPECT_STREQ(to_string(s.termination), "stalled");
  EXPECT_EQ(s.iterations, 6) << s.message;  // the first window that can be compared: iterations 1 .. 6
  EXPECT_NE(s.message.find("no progress over 5 iterations"), std::string::npos) << s.message;
  EXPECT_LT(s.objective, 100.3);
  for (const TestProblem& tp : hock_schittkowski_problems()) {
    auto problem = tp.make();
    SolverOptions plain;
    plain.solver = SolverKind::sqp;
    const SolverSummary reference = solve(*problem, plain, tp.x0);
    if (!reference.success()) continue;
    plain.sqp.progress_window = 50;
    const SolverSummary windowed = solve(*problem, plain, tp.x0);
    EXPECT_EQ(windowed.termination, reference.termination) << tp.name << ": " << windowed.message;
    EXPECT_EQ(windowed.iterations, reference.iterations) << tp.name;
  }
}

}  // namespace

namespace {

TEST(TimeLimit, IsReportedAsTimeLimit) {
  for (SolverKind kind : {SolverKind::ipopt, SolverKind::sqp}) {
    auto problem = hock_schittkowski_problems()[13].make();
    SolverOptions o;
    o.solver = kind;
    o.max_wall_seconds = 1e-9;
    const SolverSummary s = solve(*problem, o, vec({1, 2, 0, 4, 0, 1, 1}));
    EXPECT_EQ(s.termination, Termination::time_limit) << to_string(kind) << ": " << s.message;
  }
}

}  // namespace

namespace {

// Records every evaluation the solver asks the problem for.
class RecordingProblem : public Problem {
 public:
  explicit RecordingProblem(std::unique_ptr<Problem> inner) : inner_(std::move(inner)) {}
  int num_variables() const override { return inner_->num_variables(); }
  int num_equalities() const override { return inner_->num_equalities(); }
  int num_inequalities() const override { return inner_->num_inequalities(); }
  Eigen::VectorXd lower_bounds() const override { return inner_->lower_bounds(); }
  Eigen::VectorXd upper_bounds() const override { return inner_->upper_bounds(); }
  EvaluationStatus evaluate(const Eigen::VectorXd& x, bool with_derivatives, Evaluation& out) override {
    calls.push_back({x, with_derivatives});
    return inner_->evaluate(x, with_derivatives, out);
  }
  std::vector<std::pair<Eigen::VectorXd, bool>> calls;

 private:
  std::unique_ptr<Problem> inner_;
};

TEST(EvaluationCache, EachPointIsEvaluatedOnceExceptToAddDerivatives) {
  for (SolverKind kind : {SolverKind::ipopt, SolverKind::sqp}) {
    RecordingProblem problem(hock_schittkowski_problems()[11].make());  // HS71
    SolverOptions o;
    o.solver = kind;
    const SolverSummary s = solve(problem, o, vec({1, 5, 5, 1}));
    ASSERT_TRUE(s.success()) << to_string(kind);
    EXPECT_EQ(static_cast<int>(problem.calls.size()), s.function_evaluations + s.jacobian_evaluations);
    for (size_t k = 1; k < problem.calls.size(); ++k)
      if (problem.calls[k].first == problem.calls[k - 1].first) {
        EXPECT_FALSE(problem.calls[k - 1].second) << to_string(kind) << ": same point evaluated twice with derivatives";
        EXPECT_TRUE(problem.calls[k].second) << to_string(kind) << ": same point evaluated twice without derivatives";
      }
    if (kind == SolverKind::ipopt) {
      // Trial points are evaluated without derivatives; Jacobians only where Ipopt asks for
      // gradients, i.e. at the given x0 (gradient-based scaling, before x0 is pushed off the
      // bound x1 >= 1), at its iterates 0..iterations, and once more for the adapter's final
      // KKT measurement (the cache may hold a later rejected trial point by then).
      EXPECT_GT(s.function_evaluations, 0);
      EXPECT_LE(s.jacobian_evaluations, s.iterations + 3);
    }
  }
}

}  // namespace
