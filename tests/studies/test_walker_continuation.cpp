// The QPSQP continuation (seed 001, Algorithm 2) on the point-foot walker over the mean speed,
// and the sensitivity study of section 10.1 over a model parameter.
#include "cyclopt/continuation/continuation_solver.hpp"
#include "cyclopt/studies/sensitivity.hpp"
#include "cyclopt/studies/walker_family.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>

using namespace cyclopt;
using namespace cyclopt::continuation;
using namespace cyclopt::studies;

namespace {

struct PointFeet {
  walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset("point").spec);
  walker::GaitProblemOptions problem{walker::Objective::mechanical, 1.0, walker::Quadrature::trapezoid, {}};
  walker::GaitOptimum start = walker::optimise_gait(model, problem, nlp::seed_table_6_2_options());
};

const PointFeet& point_feet() {
  static const PointFeet p;
  return p;
}

void print(const ContinuationResult& r) {
  for (const CurvePoint& p : r.points)
    std::printf("p %.4f curve %d grid %d ok %d f %.6f corr %d pred %d/%d kappa %.3f Delta %.4f %.2fs\n", p.parameter,
                p.curve_id, p.on_grid, p.converged, p.objective, p.corrector.iterations, p.predictor_attempts,
                p.predictor_steps, p.kappa, p.trust_region, p.seconds);
  std::printf("%s; %zu jumps, %.1f s\n", r.message.c_str(), r.jumps.size(), r.seconds);
}

// Counts the evaluations with derivatives (Jacobians) asked of a problem.
class CountingProblem : public nlp::Problem {
 public:
  CountingProblem(std::unique_ptr<nlp::Problem> inner, int& jacobians) : inner_(std::move(inner)), jacobians_(jacobians) {}
  int num_variables() const override { return inner_->num_variables(); }
  int num_equalities() const override { return inner_->num_equalities(); }
  int num_inequalities() const override { return inner_->num_inequalities(); }
  Eigen::VectorXd lower_bounds() const override { return inner_->lower_bounds(); }
  Eigen::VectorXd upper_bounds() const override { return inner_->upper_bounds(); }
  nlp::EvaluationStatus evaluate(const Eigen::VectorXd& x, bool with_derivatives, nlp::Evaluation& out) override {
    jacobians_ += with_derivatives;
    return inner_->evaluate(x, with_derivatives, out);
  }

 private:
  std::unique_ptr<nlp::Problem> inner_;
  int& jacobians_;
};

// Both runs reach every grid value with the same optimum (relative 1e-6).
void expect_same_grid_optima(const ContinuationResult& reference, const ContinuationResult& other, std::size_t grid_size) {
  std::map<double, double> f;
  for (const CurvePoint& p : reference.points)
    if (p.on_grid) f[p.parameter] = p.objective;
  std::size_t compared = 0;
  for (const CurvePoint& p : other.points)
    if (p.on_grid) {
      ASSERT_TRUE(f.count(p.parameter)) << p.parameter;
      EXPECT_NEAR(p.objective, f[p.parameter], 1e-6 * std::abs(p.objective)) << p.parameter;
      ++compared;
    }
  EXPECT_EQ(compared, grid_size);
}

// Point feet from their 1.0 m/s optimum over kSpeeds; *jacobians (if given) counts the
// evaluations with derivatives.
const std::vector<double> kSpeeds{1.0, 1.1, 1.2, 1.3};
ContinuationResult continue_point_feet(const ContinuationOptions& o, int* jacobians) {
  const PointFeet& pf = point_feet();
  const ParametricProblem family = walker_family(pf.model, pf.problem, "speed");
  int uncounted = 0;
  int& count = jacobians ? *jacobians : uncounted;
  const ParametricProblem counted{family.parameter_name,
                                  [&](double p) { return std::make_unique<CountingProblem>(family.at(p), count); }};
  ContinuationResult r = continue_solution(counted, pf.start.z, kSpeeds, o);
  print(r);
  return r;
}

}  // namespace

TEST(WalkerContinuation, OnePredictorHessianPerPointFollowsTheSameCurveForFewerJacobians) {
  ASSERT_TRUE(point_feet().start.summary.success());
  std::map<bool, ContinuationResult> runs;
  std::map<bool, int> jacobians;
  for (const bool reuse : {false, true}) {
    ContinuationOptions o;
    o.reuse_predictor_hessian = reuse;
    runs[reuse] = continue_point_feet(o, &jacobians[reuse]);
    ASSERT_TRUE(runs[reuse].finished) << runs[reuse].message;
  }
  std::printf("Jacobians: per try %d, per point %d\n", jacobians[false], jacobians[true]);
  expect_same_grid_optima(runs[false], runs[true], kSpeeds.size());
  EXPECT_LT(jacobians[true], jacobians[false]);
}

// Point feet: the direct steps of 0.1 m/s stay on the QP predictor's curve.
TEST(WalkerContinuation, TrivialThenQpReachesTheQpOptimaByDirectSteps) {
  ASSERT_TRUE(point_feet().start.summary.success());
  std::map<Predictor, ContinuationResult> runs;
  for (const Predictor predictor : {Predictor::qp, Predictor::trivial_then_qp}) {
    ContinuationOptions o;
    o.predictor = predictor;
    runs[predictor] = continue_point_feet(o, nullptr);
    ASSERT_TRUE(runs[predictor].finished) << runs[predictor].message;
  }
  expect_same_grid_optima(runs[Predictor::qp], runs[Predictor::trivial_then_qp], kSpeeds.size());
  EXPECT_EQ(runs[Predictor::trivial_then_qp].predictor_steps, 0);
  EXPECT_GT(runs[Predictor::qp].predictor_steps, 0);
}

TEST(WalkerContinuation, BackAndForthReturnsToTheSameOptimum) {
  const PointFeet& pf = point_feet();
  ASSERT_TRUE(pf.start.summary.success());
  const ParametricProblem family = walker_family(pf.model, pf.problem, "speed");
  const ContinuationOptions o;
  const ContinuationResult up = continue_solution(family, pf.start.z, {1.0, 1.1, 1.2}, o);
  print(up);
  ASSERT_TRUE(up.finished);
  const ContinuationResult down = continue_solution(family, up.points.back().x, {1.2, 1.1, 1.0}, o);
  print(down);
  ASSERT_TRUE(down.finished);
  EXPECT_TRUE(up.jumps.empty());
  EXPECT_TRUE(down.jumps.empty());
  const CurvePoint& back = down.points.back();
  EXPECT_DOUBLE_EQ(back.parameter, 1.0);
  EXPECT_NEAR(back.objective, up.points.front().objective, 1e-6 * std::abs(up.points.front().objective));
  EXPECT_LT((back.x - up.points.front().x).lpNorm<Eigen::Infinity>(), 1e-3);
  for (const CurvePoint& p : up.points) EXPECT_TRUE(p.converged);
}

TEST(WalkerContinuation, SensitivityFollowsTheOptimumOverAModelParameter) {
  const PointFeet& pf = point_feet();
  ASSERT_TRUE(pf.start.summary.success());
  SensitivityOptions o;
  o.parameters = {"m_T"};  // torso mass
  o.relative_range = 0.04;
  o.steps = 1;
  const std::vector<SensitivityCurve> s = sensitivity(pf.model, pf.problem, pf.start.z, o);
  ASSERT_EQ(s.size(), 1u);
  for (const SensitivityPoint& p : s[0].points)
    std::printf("m_T %+.3f: delta f %+.6f (curve %d)\n", p.relative_change, p.delta_objective, p.curve_id);
  ASSERT_EQ(s[0].points.size(), 3u) << s[0].message;
  EXPECT_EQ(s[0].jumps, 0);
  EXPECT_DOUBLE_EQ(s[0].points[1].relative_change, 0.0);
  EXPECT_NEAR(s[0].points[1].delta_objective, 0.0, 1e-12);
  for (const SensitivityPoint& p : s[0].points) EXPECT_EQ(p.curve_id, 0);
}

// Step 1 from a KKT point that another solve found (here recovery R1 of a P2-shoes HMT sweep at
// 0.3 m/s, f_mech 0.003644, with the multistart's Hessian refresh off) but whose active set the
// corrector's own first test does not confirm: from W_1 = I the corrector stopped at its 300
// iterations (KKT 3.3e-4) and the sweep lost the point; from W_1 of (6.24) on differences it is
// the run's first point.
TEST(WalkerContinuation, TheFirstPointFromAnotherSolversKktPointConverges) {
  const walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset("P2-shoes-left-HMT").spec);
  const walker::GaitProblemOptions problem{walker::Objective::mechanical, 0.3, walker::Quadrature::trapezoid, {}};
  Eigen::VectorXd x0(30);
  x0 << 3.0515508562448899, 3.1683880540507259, 0.31214909787909167, 0.2343469593738112, -1.1003398695513267,
      -1.1674111731325543, 3.098657566568622, 3.0980911513329454, 0.29692919401893103, 0.35144486245335504,
      -1.1202049095409092, -1.0347712519753915, 3.1139707573868494, 3.1247339418109794, 0.34808635793174875,
      0.30474198267480546, -1.1110373559523381, -1.2457706945738145, 3.1502640231886399, 2.9301202933895296,
      0.24230367439265116, 0.31015856438282091, -1.114309015088125, -1.0167371688601476, 3.1477705904237516,
      2.9874438924278768, 0.33572654156379622, 0.31008358068979985, 2.3789055143195541, 2.2196525420306141;
  ASSERT_EQ(walker::GaitProblem(model, problem).num_variables(), x0.size());
  nlp::Evaluation at_x0;
  ASSERT_TRUE(walker::GaitProblem(model, problem).evaluate(x0, false, at_x0).ok);
  ContinuationOptions o;
  o.corrector.max_iterations = 300;  // SpeedSweepOptions::corrector_max_iterations
  const ContinuationResult r =
      continue_solution(walker_family(model, problem, "speed"), x0, {0.3, 0.4}, o, {}, [](const CurvePoint&) { return false; });
  ASSERT_EQ(r.points.size(), 1u);
  const CurvePoint& first = r.points.front();
  std::printf("first point: %s after %d iterations, f %.6f (x0: %.6f)\n", first.corrector.message.c_str(),
              first.corrector.iterations, first.objective, at_x0.objective);
  EXPECT_TRUE(first.converged) << first.corrector.message;
  EXPECT_NEAR(first.objective, at_x0.objective, 1e-3 * at_x0.objective);
}
