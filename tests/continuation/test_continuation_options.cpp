// Options, parameter grids and the jump test of the continuation (seed 001, Table 7.1), and
// Algorithm 2 on a one-variable family min (x - p)^2 whose evaluation fails beyond p = 1.05.
#include "cyclopt/continuation/continuation_solver.hpp"
#include "cyclopt/continuation/curve_jump.hpp"

#include <gtest/gtest.h>

#include <memory>

using namespace cyclopt::continuation;

namespace {

class Shifted : public cyclopt::nlp::Problem {
 public:
  explicit Shifted(double p) : p_(p) {}
  int num_variables() const override { return 1; }
  int num_equalities() const override { return 0; }
  int num_inequalities() const override { return 0; }
  cyclopt::nlp::EvaluationStatus evaluate(const Eigen::VectorXd& x, bool with_derivatives, cyclopt::nlp::Evaluation& out) override {
    if (p_ > 1.05) return cyclopt::nlp::EvaluationStatus::failure("no solution beyond p = 1.05");
    out.objective = (x[0] - p_) * (x[0] - p_);
    out.equalities.resize(0);
    out.inequalities.resize(0);
    if (with_derivatives) {
      out.gradient = Eigen::VectorXd::Constant(1, 2.0 * (x[0] - p_));
      out.equality_jacobian.resize(0, 1);
      out.inequality_jacobian.resize(0, 1);
    }
    return cyclopt::nlp::EvaluationStatus::success();
  }

 private:
  double p_;
};

const ParametricProblem shifted{"p", [](double p) { return std::make_unique<Shifted>(p); }};

}  // namespace

TEST(ContinuationOptions, DefaultsAreTable7_1AndValidate) {
  const ContinuationOptions o;
  EXPECT_DOUBLE_EQ(o.tau, 0.8);
  EXPECT_DOUBLE_EQ(o.eta, 1e-4);
  EXPECT_DOUBLE_EQ(o.min_trust_region, 0.002);
  EXPECT_NO_THROW(validate(o));
}

TEST(ContinuationOptions, ErrorsNameTheField) {
  ContinuationOptions o;
  o.tau = 1.0;
  try {
    validate(o);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("tau"), std::string::npos);
  }
  try {
    parse_predictor("tangent", "continuation.predictor");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("continuation.predictor"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("trivial_then_qp"), std::string::npos);
  }
  for (const Predictor p : {Predictor::qp, Predictor::trivial, Predictor::trivial_then_qp})
    EXPECT_EQ(parse_predictor(to_string(p)), p);
  // The spec's names (proto/schemas/job.schema.json lists the same enum).
  EXPECT_EQ(predictor_names(), (std::vector<std::string>{"qp", "trivial", "trivial_then_qp"}));
}

TEST(ContinuationOptions, ParametersMustBeMonotone) {
  const ParametricProblem none{"p", {}};
  EXPECT_THROW(continue_solution(none, Eigen::VectorXd::Zero(1), {1.0}, {}), std::invalid_argument);
  EXPECT_THROW(continue_solution(none, Eigen::VectorXd::Zero(1), {1.0, 1.2, 1.1}, {}), std::invalid_argument);
}

TEST(CurveJump, SecantFarAboveThePreviousOneIsAJump) {
  const ContinuationOptions o;
  const Eigen::VectorXd a = Eigen::VectorXd::Ones(4);
  Eigen::VectorXd near = a, far = a;
  near[0] += 0.01;
  far[0] += 1.0;
  EXPECT_FALSE(test_jump(a, near, 0.1, 0.1, o).jump);
  EXPECT_TRUE(test_jump(a, far, 0.1, 0.1, o).jump);
  EXPECT_FALSE(test_jump(a, far, 0.1, 20.0, o).jump);  // the curve itself moves that fast
  EXPECT_TRUE(test_jump(a, far, 0.1, std::nullopt, o).jump);
  EXPECT_FALSE(test_jump(a, near, 0.1, std::nullopt, o).jump);
}

TEST(CurveJump, SameOptimumNearbyIsCloserThanAJumpWithinTheSmallestStep) {
  const ContinuationOptions o;  // Delta_min 0.002, jump_min_distance 0.02
  const Eigen::VectorXd a = Eigen::VectorXd::Constant(4, 1.0);  // |a|_2 = 2
  Eigen::VectorXd close = a, apart = a;
  close[0] += 0.009;  // relative 0.0045 < 0.02 / 4
  apart[0] += 0.011;  // relative 0.0055
  EXPECT_TRUE(same_optimum_nearby(1.0, close, 1.0015, a, o));
  EXPECT_FALSE(same_optimum_nearby(1.0, apart, 1.0015, a, o));
  EXPECT_FALSE(same_optimum_nearby(1.0, close, 1.0025, a, o));  // farther than Delta_min in p
  ContinuationOptions exact = o;
  exact.jump_min_distance = 0.0;
  EXPECT_FALSE(same_optimum_nearby(1.0, close, 1.0, a, exact));
  EXPECT_TRUE(same_optimum_nearby(1.0, a, 1.0, a, exact));
}

TEST(Continuation, HitsEveryRequestedValueExactly) {
  const std::vector<double> grid{0.0, 0.1, 0.2, 0.3};
  const ContinuationResult r = continue_solution(shifted, Eigen::VectorXd::Zero(1), grid, {});
  ASSERT_TRUE(r.finished) << r.message;
  std::vector<double> hit;
  for (const CurvePoint& p : r.points) {
    EXPECT_TRUE(p.converged);
    EXPECT_NEAR(p.x[0], p.parameter, 1e-6);
    EXPECT_EQ(p.curve_id, 0);
    if (p.on_grid) hit.push_back(p.parameter);
  }
  EXPECT_EQ(hit, grid);
  EXPECT_TRUE(r.jumps.empty());
}

// trivial_then_qp on a smooth curve: every requested value by its direct step, no QP predictor.
TEST(Continuation, TrivialThenQpStepsDirectlyWhereTheCurveIsSmooth) {
  const std::vector<double> grid{0.0, 0.1, 0.2, 0.3};
  ContinuationOptions o;
  o.predictor = Predictor::trivial_then_qp;
  const ContinuationResult r = continue_solution(shifted, Eigen::VectorXd::Zero(1), grid, o);
  ASSERT_TRUE(r.finished) << r.message;
  ASSERT_EQ(r.points.size(), grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    EXPECT_EQ(r.points[i].parameter, grid[i]);
    EXPECT_NEAR(r.points[i].x[0], grid[i], 1e-6);
    EXPECT_EQ(r.points[i].predictor_attempts, 0);
  }
  EXPECT_EQ(r.predictor_steps, 0);
}

// Where the direct step fails (no solution at 1.1), the QP predictor's trust region takes over.
TEST(Continuation, StopsAtTheMinimalStepWhereTheCorrectorKeepsFailing) {
  for (const Predictor predictor : {Predictor::qp, Predictor::trivial, Predictor::trivial_then_qp}) {
    ContinuationOptions o;
    o.predictor = predictor;
    const ContinuationResult r = continue_solution(shifted, Eigen::VectorXd::Zero(1), {1.0, 1.1}, o);
    EXPECT_FALSE(r.finished);
    EXPECT_NE(r.message.find("minimal step"), std::string::npos) << r.message;
    double last = 0.0;
    for (const CurvePoint& p : r.points)
      if (p.converged) last = p.parameter;
    EXPECT_GT(last, 1.05 - 2 * o.min_trust_region);
    EXPECT_LE(last, 1.05);
    EXPECT_LT(r.points.size(), 60u);
  }
}

// A run resumed from where it stood after any converged point (RunState, as a crashed sweep's
// journal holds it) computes the same points as the run that was not interrupted, bit for bit,
// and solves only the points after that state (issue 57 item 2). Two grids: one the run reaches,
// one where the corrector fails beyond p = 1.05 and the trust region shrinks to its minimum.
TEST(Continuation, ResumedFromAnyConvergedPointGivesTheUninterruptedRun) {
  for (const std::vector<double>& grid : {std::vector<double>{0.0, 0.35, 0.7, 1.0}, std::vector<double>{0.8, 1.1}})
    for (const Predictor predictor : {Predictor::qp, Predictor::trivial, Predictor::trivial_then_qp}) {
      ContinuationOptions o;
      o.predictor = predictor;
      std::vector<RunState> states;
      const ContinuationResult whole =
          continue_solution(shifted, Eigen::VectorXd::Zero(1), grid, o, {}, {}, [&](const RunState& s) { states.push_back(s); });
      ASSERT_GE(states.size(), 2u);
      for (const RunState& state : states) {
        std::size_t solved = 0;
        const ContinuationResult resumed =
            resume_solution(shifted, state, grid, o, [&](const CurvePoint&) { return ++solved, true; });
        ASSERT_EQ(resumed.points.size(), whole.points.size());
        EXPECT_EQ(solved, whole.points.size() - state.result.points.size());
        for (std::size_t i = 0; i < whole.points.size(); ++i) {
          EXPECT_EQ(resumed.points[i].parameter, whole.points[i].parameter) << i;
          EXPECT_EQ(resumed.points[i].x, whole.points[i].x) << i;
          EXPECT_EQ(resumed.points[i].converged, whole.points[i].converged) << i;
          EXPECT_EQ(resumed.points[i].trust_region, whole.points[i].trust_region) << i;
        }
        EXPECT_EQ(resumed.finished, whole.finished);
        EXPECT_EQ(resumed.message, whole.message);
        EXPECT_EQ(resumed.corrector_iterations, whole.corrector_iterations);
      }
    }
}
