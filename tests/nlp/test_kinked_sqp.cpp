// The SQP with the objective's kinked terms modelled (issue 52, SqpOptions::kinks): the kinked QP
// subproblem and the nonsmooth (Clarke) stationarity test on problems whose minimisers are known by
// hand, and the full SQP on a nonsmooth problem shaped like f_mech at a held joint - many
// positive-part samples vanishing together on one kink - reaching the known minimiser as a
// nonsmooth KKT point.
#include "autodiff_problem.hpp"

#include "cyclopt/autodiff/dual.hpp"
#include "cyclopt/nlp/active_set_projections.hpp"
#include "cyclopt/nlp/clarke_stationarity.hpp"
#include "cyclopt/nlp/kinked_terms.hpp"
#include "cyclopt/nlp/solve.hpp"
#include "cyclopt/nlp/sqp_subproblems.hpp"
#include "cyclopt/qp/positive_part_qp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using namespace cyclopt::nlp;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// One kinked sample of a hand-made evaluation: n = 2, p = a'x + p0, weight w, no partner.
Evaluation one_kink(const VectorXd& gradient, const VectorXd& a, double p, double w, double slope) {
  Evaluation e;
  e.objective = 0.0;
  e.gradient = gradient;
  e.equalities = VectorXd(0);
  e.equality_jacobian = MatrixXd(0, gradient.size());
  e.inequalities = VectorXd(0);
  e.inequality_jacobian = MatrixXd(0, gradient.size());
  e.kinks.values = VectorXd::Constant(1, p);
  e.kinks.jacobian = a.transpose();
  e.kinks.terms = {{0, -1, w, slope}};
  return e;
}

VectorXd v2(double a, double b) { return (VectorXd(2) << a, b).finished(); }

// f = g_s'x + w max(x1 - x2, 0) near x = 0 (slope taken: w, the branch p >= 0). The Clarke
// gradients are g_s + sigma (1, -1), sigma in [0, w]; with g_s = (-D + delta, D + delta) the least
// |.|_inf over them is |delta| when D <= w (sigma = D), and max(|delta|, D - w + ...) beyond.
TEST(ClarkeStationarity, AcceptsAClarkePointAndMeasuresTheDistanceOfOthers) {
  const double w = 2.0, D = 0.75;
  const VectorXd a = v2(1.0, -1.0);
  const ActiveConstraints none;
  const VectorXd x = VectorXd::Zero(2), lo = VectorXd::Constant(2, -1e20), hi = VectorXd::Constant(2, 1e20);
  for (double delta : {0.0, 1e-3, -0.2}) {
    SCOPED_TRACE("delta " + std::to_string(delta));
    const Evaluation e = one_kink(v2(-D + delta + w, D + delta - w), a, 0.0, w, w);  // gradient = g_s + w a
    const NearKinks near = near_kinks(e.kinks, 1e-6);
    ASSERT_EQ(near.size(), 1);
    const ClarkeMultipliers c = clarke_multipliers(e, none, near, x, lo, hi, 1e-8);
    EXPECT_NEAR(c.residual, std::abs(delta), 1e-13);
    EXPECT_NEAR(c.kink[0], D, 1e-12);
    // Without the kink's subgradients (the smooth test) the same point is off by D - w + ... : rejected.
    const ClarkeMultipliers smooth = clarke_multipliers(e, none, {}, x, lo, hi, 1e-8);
    EXPECT_GE(smooth.residual, 0.5);
  }
  // A subgradient outside [0, w] is not admitted: g_s = (-3, 3) needs sigma = 3 > w.
  const Evaluation far = one_kink(v2(-3.0 + w, 3.0 - w), a, 0.0, w, w);
  EXPECT_NEAR(clarke_multipliers(far, none, near_kinks(far.kinks, 1e-6), x, lo, hi, 1e-8).residual, 1.0, 1e-13);
  // A sample away from its kink (p = 0.5, beyond the band) keeps its slope: not a Clarke point.
  const Evaluation off = one_kink(v2(-D + w, D - w), a, 0.5, w, w);
  EXPECT_TRUE(near_kinks(off.kinks, 1e-3).empty());
}

TEST(ClarkeStationarity, InequalityMultipliersKeepTheirSign) {
  // f = x1 with the active inequality c = x1 - 1 <= 0 or c = 1 - x1 <= 0 at x1 = 1.
  for (double sign : {1.0, -1.0}) {
    Evaluation e = one_kink(v2(1.0, 0.0), v2(0.0, 1.0), 5.0, 1.0, 1.0);
    e.inequalities = VectorXd::Zero(1);
    e.inequality_jacobian = (MatrixXd(1, 2) << sign, 0.0).finished();
    ActiveConstraints active{{0}, {}};
    const VectorXd x = v2(1.0, 0.0), lo = VectorXd::Constant(2, -1e20), hi = VectorXd::Constant(2, 1e20);
    const ClarkeMultipliers c = clarke_multipliers(e, active, near_kinks(e.kinks, 1e-6), x, lo, hi, 1e-8);
    // sign -1: y = 1 >= 0 makes grad L vanish (a KKT point); sign +1 would need y = -1: rejected.
    EXPECT_NEAR(c.residual, sign < 0 ? 0.0 : 1.0, 1e-14);
    EXPECT_GE(c.inequality[0], 0.0);
  }
}

// The kinked QP (sqp_subproblems.hpp) of  min 1/2 |d|^2 + g'd + w |d1 - d2|  s.t. d1 + d2 >= 1,
// g = (-G, G), written with two kinked samples p = +-(d1 - d2): for G <= w the minimiser is
// d = (0.5, 0.5) with sigma = G on the first sample, and the constraint's multiplier 0.5.
TEST(KinkedSubproblem, ReachesTheKnownMinimiserOnTheKink) {
  const double w = 1.0, G = 0.6;
  Evaluation e;
  e.objective = 0.0;
  e.gradient = v2(-G, G);
  e.equalities = VectorXd(0);
  e.equality_jacobian = MatrixXd(0, 2);
  e.inequalities = VectorXd::Constant(1, 1.0);  // c(0) + J d <= 0 with c = 1 - d1 - d2
  e.inequality_jacobian = (MatrixXd(1, 2) << -1.0, -1.0).finished();
  e.kinks.values = VectorXd::Zero(2);
  e.kinks.jacobian = (MatrixXd(2, 2) << 1.0, -1.0, -1.0, 1.0).finished();
  e.kinks.terms = {{0, -1, w, w}, {1, -1, w, w}};  // the gradient took slope w on both (p >= 0)
  e.gradient += w * (e.kinks.jacobian.row(0) + e.kinks.jacobian.row(1)).transpose();
  const VectorXd x = VectorXd::Zero(2), lo = VectorXd::Constant(2, -1e20), hi = VectorXd::Constant(2, 1e20);
  const KinkedSubproblem sub = kinked_sqp_subproblem({e, x, lo, hi}, MatrixXd::Identity(2, 2), near_kinks(e.kinks, 1e-6));
  const cyclopt::qp::PositivePartQpSolution s = cyclopt::qp::solve_positive_part_qp(sub.qp, sub.terms);
  ASSERT_EQ(s.qp.status, cyclopt::qp::QpStatus::optimal) << s.qp.message;
  EXPECT_NEAR(s.qp.x[0], 0.5, 1e-12);
  EXPECT_NEAR(s.qp.x[1], 0.5, 1e-12);
  EXPECT_NEAR(s.qp.inequality_multipliers[0], 0.5, 1e-12);
  // sigma of p1 = d1 - d2 minus that of p2 = -p1 is G; each in [0, w].
  EXPECT_NEAR(s.sigma[0] - s.sigma[1], G, 1e-12);
  EXPECT_GE(s.sigma.minCoeff(), 0.0);
  EXPECT_LE(s.sigma.maxCoeff(), w);
  EXPECT_NEAR(s.qp.objective, 0.25, 1e-12);  // 1/2 |d|^2 + g'd + w |d1 - d2| at d = (0.5, 0.5)
}

// The second-order correction with held kinks (active_set_projections.hpp) solves the kink rows
// p_s + grad p_s' d = 0 with the constraints, and is the shortest such step.
TEST(KinkedSecondOrderCorrection, HoldsTheKinksAndIsTheShortestStep) {
  Evaluation trial = one_kink(v2(0.0, 0.0), v2(1.0, 2.0), 0.3, 1.0, 1.0);
  trial.equalities = VectorXd::Constant(1, -0.5);
  trial.equality_jacobian = (MatrixXd(1, 2) << 1.0, -1.0).finished();
  const VectorXd d = second_order_correction(trial, {}, {0});
  EXPECT_NEAR(trial.kinks.values[0] + trial.kinks.jacobian.row(0).dot(d), 0.0, 1e-14);
  EXPECT_NEAR(trial.equalities[0] + trial.equality_jacobian.row(0).dot(d), 0.0, 1e-14);
  // Two rows in two unknowns: the unique solution of [1 -1; 1 2] d = [0.5; -0.3].
  EXPECT_NEAR(d[0], (2.0 * 0.5 - 0.3) / 3.0, 1e-14);
  EXPECT_NEAR(d[1], (-0.3 - 0.5) / 3.0, 1e-14);
  // Without the kink: the shortest step of the equality alone, d = 0.5 (1, -1) / 2.
  const VectorXd d0 = second_order_correction(trial, {});
  EXPECT_NEAR(d0[0], 0.25, 1e-14);
  EXPECT_NEAR(d0[1], -0.25, 1e-14);
}

// f(x) = 1/2 |x - c|^2 + sum_k w max(p_k, 0),  p_k = s_k (1 + 0.1 k)(1 + 0.1 x3^2)(x1 - x2),
// s_k = +1, -1, +1, ...: six samples on one kink x1 = x2, as the powers of a joint held still;
// s.t. x4 - x1 - x2 = 0, c3 + 0.5 - x3 <= 0. Minimiser by hand: x1 = x2 = m = (c1 + c2 + 2 c4) / 6,
// x3 = c3 + 0.5, x4 = 2m, with the kink's subgradient c1 + c4 - 3m inside the samples' range.
class HeldJointProblem : public Problem {
 public:
  static constexpr int kSamples = 6;
  static constexpr double kWeight = 0.5;
  static inline const VectorXd c = (VectorXd(4) << 1.0, -1.0, 0.2, 0.5).finished();
  static double m() { return (c[0] + c[1] + 2.0 * c[3]) / 6.0; }
  static VectorXd minimiser() { return (VectorXd(4) << m(), m(), c[2] + 0.5, 2.0 * m()).finished(); }
  static double minimum() {
    const VectorXd r = minimiser() - c;
    return 0.5 * r.squaredNorm();
  }

  int num_variables() const override { return 4; }
  int num_equalities() const override { return 1; }
  int num_inequalities() const override { return 1; }
  EvaluationStatus evaluate(const VectorXd& x, bool with_derivatives, Evaluation& out) override {
    using D = cyclopt::ad::Dual<4>;
    std::array<D, 4> xd;
    for (int i = 0; i < 4; ++i) xd[static_cast<size_t>(i)] = D::variable(x[i], i);
    D f = 0.0;
    for (int i = 0; i < 4; ++i) f += 0.5 * (xd[static_cast<size_t>(i)] - c[i]) * (xd[static_cast<size_t>(i)] - c[i]);
    out.kinks.values.resize(kSamples);
    out.kinks.jacobian.resize(kSamples, 4);
    out.kinks.terms.clear();
    for (int k = 0; k < kSamples; ++k) {
      const double s = k % 2 == 0 ? 1.0 : -1.0;
      const D p = s * (1.0 + 0.1 * k) * (1.0 + 0.1 * xd[2] * xd[2]) * (xd[0] - xd[1]);
      const bool positive = p.v > 0.0;
      if (positive) f += kWeight * p;
      out.kinks.values[k] = p.v;
      out.kinks.jacobian.row(k) = p.d.transpose();
      out.kinks.terms.push_back({k, -1, kWeight, positive ? kWeight : 0.0});
    }
    const D eq = xd[3] - xd[0] - xd[1];
    const D in = c[2] + 0.5 - xd[2];
    out.objective = f.v;
    out.equalities = VectorXd::Constant(1, eq.v);
    out.inequalities = VectorXd::Constant(1, in.v);
    if (!with_derivatives) {
      out.kinks = {};
      return EvaluationStatus::success();
    }
    out.gradient = f.d;
    out.equality_jacobian = eq.d.transpose();
    out.inequality_jacobian = in.d.transpose();
    return EvaluationStatus::success();
  }
};

SolverOptions kinked_sqp() {
  SolverOptions o = seed_table_6_2_options();
  o.optimality_tolerance = 1e-9;
  o.max_iterations = 300;
  o.sqp.kinks.enabled = true;
  return o;
}

TEST(KinkedSqp, ReachesTheMinimiserOfAHeldJointAsANonsmoothKktPoint) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal;
  for (int start = 0; start < 8; ++start) {
    SCOPED_TRACE("start " + std::to_string(start));
    const VectorXd x0 = HeldJointProblem::minimiser() + VectorXd::NullaryExpr(4, [&] { return 0.5 * normal(rng); });
    HeldJointProblem problem;
    const SolverSummary s = solve(problem, kinked_sqp(), x0);
    ASSERT_EQ(s.termination, Termination::converged) << s.message;
    EXPECT_EQ(s.optimality, Optimality::nonsmooth_kkt);
    EXPECT_LE((s.x - HeldJointProblem::minimiser()).lpNorm<Eigen::Infinity>(), 1e-6);
    EXPECT_NEAR(s.objective, HeldJointProblem::minimum(), 1e-9);
    // Its multipliers: the equality's and the inequality's by hand, sigma in [0, w].
    EXPECT_NEAR(s.inequality_multipliers[0], 0.5, 1e-6);
    ASSERT_EQ(s.kink_multipliers.size(), HeldJointProblem::kSamples);
    EXPECT_GE(s.kink_multipliers.minCoeff(), 0.0);
    EXPECT_LE(s.kink_multipliers.maxCoeff(), HeldJointProblem::kWeight);
  }
}

// A problem that declares no kinks is solved exactly as without the option (the seed's SQP), and a
// smooth optimum is reported as a (smooth) KKT point.
struct Quadratic {
  static constexpr int n = 2, m_eq = 1, m_in = 1;
  template <class T>
  static void evaluate(const T* x, T& f, T* c_eq, T* c_in) {
    f = (x[0] - 1.0) * (x[0] - 1.0) + 2.0 * (x[1] + 0.5) * (x[1] + 0.5) + x[0] * x[1];
    c_eq[0] = x[0] + 2.0 * x[1] - 0.3;
    c_in[0] = x[0] * x[0] - 0.5;
  }
};

TEST(KinkedSqp, WithoutDeclaredKinksTheSolveIsTheSeedsBitForBit) {
  cyclopt::nlp::testing::AutodiffProblem<Quadratic> a, b;
  const VectorXd x0 = v2(2.0, 1.0);
  const SolverSummary with = solve(a, kinked_sqp(), x0);
  SolverOptions o = kinked_sqp();
  o.sqp.kinks.enabled = false;
  const SolverSummary without = solve(b, o, x0);
  ASSERT_EQ(with.termination, Termination::converged);
  EXPECT_EQ(with.optimality, Optimality::kkt);
  EXPECT_EQ(with.iterations, without.iterations);
  EXPECT_TRUE(with.x == without.x);
  EXPECT_EQ(with.objective, without.objective);
}

TEST(KinkedSqp, OptionsOutsideTheirRangeAreNamed) {
  SolverOptions o = kinked_sqp();
  o.sqp.kinks.test_band = 2.0 * o.sqp.kinks.model_band;
  try {
    validate(o);
    FAIL() << "accepted test_band > model_band";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sqp.kinks.test_band"), std::string::npos);
  }
}

}  // namespace
