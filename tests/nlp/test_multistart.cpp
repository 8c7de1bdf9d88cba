// Multistart: same seeds give the same starts, results and ranking for any number of threads;
// duplicates of one optimum are merged.
#include "autodiff_problem.hpp"

#include "cyclopt/nlp/multistart.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace {

using namespace cyclopt::nlp;

// Four local minima near (+-1, +-1), tilted so that their objectives differ; one inequality.
struct FourWells {
  static constexpr int n = 2, m_eq = 0, m_in = 1;
  template <class T> static void evaluate(const T* x, T& f, T*, T* in) {
    f = (x[0] * x[0] - 1.0) * (x[0] * x[0] - 1.0) + (x[1] * x[1] - 1.0) * (x[1] * x[1] - 1.0) + 0.1 * x[0] + 0.05 * x[1];
    in[0] = x[0] + x[1] - 1.5;
  }
};

MultistartResult run(SolverKind kind, int threads) {
  MultistartOptions o;
  o.num_starts = 24;
  o.base_seed = 1234;
  o.num_threads = threads;
  o.solver.solver = kind;
  return multistart([] { return std::make_unique<cyclopt::nlp::testing::AutodiffProblem<FourWells>>(); },
                    [](std::mt19937_64& rng) {
                      std::uniform_real_distribution<double> u(-2.0, 2.0);
                      Eigen::VectorXd x(2);
                      x[0] = u(rng);
                      x[1] = u(rng);
                      return x;
                    },
                    o);
}

TEST(Multistart, ReproducibleRegardlessOfThreadCountAndMergesDuplicates) {
  for (SolverKind kind : {SolverKind::sqp, SolverKind::ipopt}) {
    const MultistartResult one = run(kind, 1);
    const MultistartResult many = run(kind, 3);
    const MultistartResult all = run(kind, 0);
    std::printf("multistart %s: %d/%d successes, %zu distinct optima, best f = %.10f, %.3f s (1 thread) %.3f s (all)\n",
                to_string(kind), one.successes, static_cast<int>(one.runs.size()), one.optima.size(),
                one.optima.empty() ? 0.0 : one.optima.front().objective, one.wall_seconds, all.wall_seconds);
    for (const MultistartResult* other : {&many, &all}) {
      ASSERT_EQ(one.ranking, other->ranking);
      for (size_t i = 0; i < one.runs.size(); ++i) {
        EXPECT_EQ(one.starts[i], other->starts[i]);
        EXPECT_EQ(one.runs[i].x, other->runs[i].x);  // bitwise: deterministic solves
      }
      ASSERT_EQ(one.optima.size(), other->optima.size());
      for (size_t k = 0; k < one.optima.size(); ++k) EXPECT_EQ(one.optima[k].starts, other->optima[k].starts);
    }
    EXPECT_EQ(one.successes, 24);
    // Wells at (+-1, +-1) minus the one cut off by x1 + x2 <= 1.5, plus possibly a constrained point.
    EXPECT_GE(one.optima.size(), 3u);
    size_t merged = 0;
    for (const MultistartOptimum& o : one.optima) merged += o.starts.size();
    EXPECT_EQ(merged, 24u);
    for (size_t k = 1; k < one.optima.size(); ++k) EXPECT_LE(one.optima[k - 1].objective, one.optima[k].objective);
    // The best well is (-1, -1): f = -0.15 to first order.
    EXPECT_LT(one.optima.front().x[0], 0.0);
    EXPECT_LT(one.optima.front().x[1], 0.0);
  }
}

// Runs one at a time with the SQP, at most max_iterations each.
MultistartOptions sqp_on_one_thread(int max_iterations) {
  MultistartOptions o;
  o.num_threads = 1;
  o.solver.solver = SolverKind::sqp;
  o.solver.max_iterations = max_iterations;
  return o;
}

TEST(Multistart, RestartsTakeARunThatStoppedEarlyToItsKktPoint) {
  // Two SQP iterations per solve do not reach a minimum from (2, -2); solving again from the
  // final point a few times does, and the run adds up the work of every solve.
  MultistartOptions o = sqp_on_one_thread(2);
  const auto factory = [] { return std::make_unique<cyclopt::nlp::testing::AutodiffProblem<FourWells>>(); };
  const std::vector<Eigen::VectorXd> start{Eigen::Vector2d(2.0, -2.0)};
  const MultistartResult once = multistart_from(factory, start, o);
  ASSERT_FALSE(once.runs[0].success()) << once.runs[0].message;
  o.restarts = 30;
  const MultistartResult restarted = multistart_from(factory, start, o);
  const SolverSummary& run = restarted.runs[0];
  ASSERT_TRUE(run.success()) << run.message;
  EXPECT_EQ(restarted.successes, 1);
  EXPECT_GT(run.iterations, 2);
  EXPECT_NE(run.message.find("restart"), std::string::npos) << run.message;
  o.restarts = 0;
  o.solver.max_iterations = 500;
  const MultistartResult unlimited = multistart_from(factory, start, o);  // the optimum one solve reaches
  ASSERT_TRUE(unlimited.runs[0].success()) << unlimited.runs[0].message;
  EXPECT_LT((run.x - unlimited.runs[0].x).lpNorm<Eigen::Infinity>(), 1e-4);
  o.restarts = -1;
  EXPECT_THROW(multistart_from(factory, start, o), std::invalid_argument);
}

// On the circle x0^2 + x1^2 = 4, nearest to (3, 1).
struct CirclePoint {
  static constexpr int n = 2, m_eq = 1, m_in = 0;
  template <class T> static void evaluate(const T* x, T& f, T* eq, T*) {
    f = (x[0] - 3.0) * (x[0] - 3.0) + (x[1] - 1.0) * (x[1] - 1.0);
    eq[0] = x[0] * x[0] + x[1] * x[1] - 4.0;
  }
};

TEST(Multistart, RestartsOnlyRunsThatEndedNearlyFeasible) {
  // One SQP iteration from (3, 3) leaves the circle: the run ends infeasible, with violation v.
  MultistartOptions o = sqp_on_one_thread(1);
  const auto factory = [] { return std::make_unique<cyclopt::nlp::testing::AutodiffProblem<CirclePoint>>(); };
  const std::vector<Eigen::VectorXd> start{Eigen::Vector2d(3.0, 3.0)};
  const MultistartResult once = multistart_from(factory, start, o);
  const double v = once.runs[0].constraint_violation;
  ASSERT_FALSE(once.runs[0].success()) << once.runs[0].message;
  ASSERT_GT(v, 1e-3);
  o.restarts = 1;
  o.restart_max_violation = 0.5 * v;
  const MultistartResult kept = multistart_from(factory, start, o);
  EXPECT_EQ(kept.runs[0].message.find("restart"), std::string::npos) << kept.runs[0].message;
  EXPECT_EQ(kept.runs[0].iterations, once.runs[0].iterations);
  o.restart_max_violation = 2.0 * v;
  const MultistartResult restarted = multistart_from(factory, start, o);
  EXPECT_NE(restarted.runs[0].message.find("restart 1"), std::string::npos) << restarted.runs[0].message;
  EXPECT_GT(restarted.runs[0].iterations, once.runs[0].iterations);
  o.restart_max_violation = -1.0;
  EXPECT_THROW(multistart_from(factory, start, o), std::invalid_argument);
}

TEST(Multistart, KktOnlyRestartsAcceptableRunsAndLeavesOutThoseThatStayAcceptable) {
  // A TolStep far above the steps makes each SQP solve stop at its first step as "acceptable"
  // (Algorithm 1 step 3) without moving: a potential KKT point that is none.
  MultistartOptions o;
  o.num_threads = 1;
  o.solver.solver = SolverKind::sqp;
  o.solver.sqp.step_tolerance = 100.0;
  o.restarts = 2;
  const auto factory = [] { return std::make_unique<cyclopt::nlp::testing::AutodiffProblem<FourWells>>(); };
  const std::vector<Eigen::VectorXd> starts{Eigen::Vector2d(2.0, -2.0), Eigen::Vector2d(-0.5, 0.5)};
  const MultistartResult loose = multistart_from(factory, starts, o);
  ASSERT_EQ(loose.runs[0].termination, Termination::acceptable) << loose.runs[0].message;
  EXPECT_EQ(loose.successes, 2);
  EXPECT_EQ(loose.runs[0].message.find("restart"), std::string::npos) << "an accepted run was restarted";
  o.acceptance = Acceptance::kkt_only;
  const MultistartResult strict = multistart_from(factory, starts, o);
  EXPECT_EQ(strict.successes, 0);
  EXPECT_TRUE(strict.optima.empty());
  EXPECT_TRUE(strict.ranking.empty());
  // Its solve ended at its start, so a restart would repeat it: none is made (solve_with_restarts).
  EXPECT_EQ(strict.runs[0].message.find("restart"), std::string::npos) << strict.runs[0].message;
  EXPECT_EQ(strict.runs[0].iterations, loose.runs[0].iterations);
  // Recorded runs (a resumed multistart) are judged alike: a converged one counts, an acceptable one not.
  SolverSummary kkt = loose.runs[1];
  kkt.termination = Termination::converged;
  o.recorded_run = [&](int i) { return i == 0 ? loose.runs[0] : kkt; };
  const MultistartResult replayed = multistart_from(factory, starts, o);
  EXPECT_EQ(replayed.successes, 1);
  ASSERT_EQ(replayed.optima.size(), 1u);
  EXPECT_EQ(replayed.optima[0].starts, std::vector<int>{1});
}

TEST(Multistart, RejectsBadOptions) {
  MultistartOptions o;
  o.num_starts = 0;
  EXPECT_THROW(multistart({}, {}, o), std::invalid_argument);
}

}  // namespace
