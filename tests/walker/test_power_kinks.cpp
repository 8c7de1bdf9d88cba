// f_mech's kinked terms (power_kinks.hpp, issue 52): the joint powers' derivatives against the
// complex step on the templated gait, the terms' slopes and weights against central differences
// of the seed's rule (5.102 with Fig. 5.3) in the power samples, and which problems declare them.
#include "reference_gaits.hpp"

#include "cyclopt/walker/gait_problem.hpp"
#include "cyclopt/walker/positive_power.hpp"
#include "cyclopt/walker/power_kinks.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <limits>
#include <random>

namespace cyclopt::walker {
namespace {

using C = std::complex<double>;
constexpr double kStep = 1e-30;

TEST(PowerKinks, JointPowerJacobianMatchesComplexStep) {
  const auto& ref = testing::reference_gait("P2-shoes-left-HMT");
  ASSERT_TRUE(ref.start.feasible) << ref.start.message;
  const GaitEvaluator& ev = *ref.evaluator;
  const WalkerModel<C> mc = cast_model<C>(ev.model());
  const GaitOptions opt{Objective::mechanical, 1.3, false};
  std::mt19937_64 rng(52);
  double worst = 0.0;
  int entries = 0, kept = 0;
  for (int draws = 0; kept < 3 && draws < 200; ++draws) {
    const Eigen::VectorXd x = perturbed_gait(ev, ref.start.x, 0.01, rng);
    const GaitEvaluation e = ev.evaluate_with_derivatives(x, opt);
    if (!e.gait.real) continue;
    ++kept;
    const Eigen::Index joints = e.gait.joint_power.rows(), points = e.gait.joint_power.cols();
    ASSERT_EQ(e.derivatives.joint_power.rows(), joints * points);
    for (int j = 0; j < x.size(); ++j) {
      Eigen::VectorXcd xc = x.cast<C>();
      xc(j) += C(0.0, kStep);
      const PeriodicGait<C> g = periodic_gait(mc, ev.basis(), xc, opt);
      ASSERT_TRUE(g.real);
      for (Eigen::Index a = 0; a < joints; ++a)
        for (Eigen::Index i = 0; i < points; ++i) {
          const double cs = g.joint_power(a, i).imag() / kStep;
          EXPECT_NEAR(g.joint_power(a, i).real(), e.gait.joint_power(a, i), 1e-12 * (1.0 + e.gait.joint_power.cwiseAbs().maxCoeff()));
          if (std::abs(cs) < 1e-6) continue;
          worst = std::max(worst, std::abs(e.derivatives.joint_power(a * points + i, j) - cs) / std::abs(cs));
          ++entries;
        }
    }
  }
  ASSERT_EQ(kept, 3);
  EXPECT_GT(entries, 1000);
  EXPECT_LE(worst, 1e-7);  // as the gait's other outputs (test_gait_derivatives.cpp)
}

// F(p) = sum_j sum_i positive_part_trapezoid(p_ji, p_j,i+1, dt_i) / W: the part of f_mech the terms
// describe. Per sample, the slopes of its terms sum to dF/dp_s (central differences at samples away
// from zero), and each term's weight is its interval's dt / (2 W).
TEST(PowerKinks, SlopesAreTheRulesDerivativeAndWeightsItsJump) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  const int joints = 3, points = 12;
  Eigen::MatrixXd power = Eigen::MatrixXd::NullaryExpr(joints, points, [&] { return 5.0 * normal(rng); });
  Eigen::VectorXd time(points);
  time[0] = 0.0;
  for (int i = 1; i < points; ++i) time[i] = time[i - 1] + 0.01 + 0.005 * std::abs(normal(rng));
  const double W = 412.0;
  const auto rule = [&](const Eigen::MatrixXd& p) {
    double sum = 0.0;
    for (int j = 0; j < joints; ++j)
      for (int i = 0; i + 1 < points; ++i) sum += positive_part_trapezoid(p(j, i), p(j, i + 1), time[i + 1] - time[i]);
    return sum / W;
  };
  const nlp::KinkedTerms k = mechanical_power_kinks(power, Eigen::MatrixXd::Zero(joints * points, 2),
                                                    time.tail(points - 1) - time.head(points - 1), W);
  ASSERT_EQ(k.values.size(), joints * points);
  ASSERT_EQ(k.terms.size(), static_cast<size_t>(2 * joints * (points - 1)));
  Eigen::VectorXd slope_sum = Eigen::VectorXd::Zero(joints * points);
  for (const nlp::KinkedTerm& t : k.terms) {
    slope_sum[t.sample] += t.slope;
    const int i = std::min(t.sample, t.partner) % points;
    EXPECT_EQ(std::abs(t.sample - t.partner), 1);
    EXPECT_NEAR(t.weight, 0.5 * (time[i + 1] - time[i]) / W, 1e-18);
    EXPECT_GE(t.slope, 0.0);
    EXPECT_LE(t.slope, t.weight * (1.0 + 1e-12));
  }
  for (int j = 0; j < joints; ++j)
    for (int i = 0; i < points; ++i) {
      const int s = j * points + i;
      EXPECT_EQ(k.values[s], power(j, i));
      const double h = 1e-6 * std::max(1.0, std::abs(power(j, i)));
      Eigen::MatrixXd plus = power, minus = power;
      plus(j, i) += h;
      minus(j, i) -= h;
      EXPECT_NEAR(slope_sum[s], (rule(plus) - rule(minus)) / (2.0 * h), 1e-8 * slope_sum.maxCoeff()) << "sample " << s;
    }
}

// A gait stepping backwards (m g L <= 0, met by foot-design solves) would give the positive parts
// negative weights - concave, no kinks of the l1 kind - and a non-finite power or derivative has no
// kink to model: none are declared.
TEST(PowerKinks, NoneAtABackwardStepOrANonFinitePower) {
  const Eigen::MatrixXd power = (Eigen::MatrixXd(1, 3) << 1.0, -2.0, 0.5).finished();
  const Eigen::MatrixXd jacobian = Eigen::MatrixXd::Ones(3, 2);
  const Eigen::VectorXd durations = Eigen::VectorXd::Constant(2, 0.01);
  EXPECT_FALSE(mechanical_power_kinks(power, jacobian, durations, 412.0).empty());
  EXPECT_TRUE(mechanical_power_kinks(power, jacobian, durations, -412.0).empty());
  EXPECT_TRUE(mechanical_power_kinks(power, jacobian, durations, 0.0).empty());
  Eigen::MatrixXd nan_power = power, nan_jacobian = jacobian;
  nan_power(0, 1) = std::numeric_limits<double>::quiet_NaN();
  nan_jacobian(2, 0) = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(mechanical_power_kinks(nan_power, jacobian, durations, 412.0).empty());
  EXPECT_TRUE(mechanical_power_kinks(power, nan_jacobian, durations, 412.0).empty());
}

TEST(PowerKinks, DeclaredForTheSeedsRuleOnly) {
  const WalkerModel<double> model = testing::reference_model("point", 60);
  const auto declares = [&](Objective o, Quadrature q, double band) {
    GaitProblemOptions po;
    po.objective = o;
    po.quadrature = q;
    po.positive_power_band = band;
    return GaitProblem(model, po).declares_kinks();
  };
  EXPECT_TRUE(declares(Objective::mechanical, Quadrature::trapezoid, 0.0));
  EXPECT_FALSE(declares(Objective::mechanical, Quadrature::trapezoid, 1e-3));
  EXPECT_FALSE(declares(Objective::mechanical, Quadrature::corrected_trapezoid, 0.0));
  EXPECT_FALSE(declares(Objective::squared_torque, Quadrature::trapezoid, 0.0));
  // An evaluation with derivatives carries them: one sample per joint and grid point.
  GaitProblem p(model, GaitProblemOptions{});
  const GaitEvaluator ev(model);
  const StartingGait sg = starting_gait(ev, StartingGaitOptions{});
  ASSERT_TRUE(sg.real);
  nlp::Evaluation e;
  ASSERT_TRUE(p.evaluate(p.initial_point(sg.x), true, e).ok);
  EXPECT_EQ(e.kinks.values.size(), model.joint_count * 60);
  EXPECT_EQ(e.kinks.jacobian.cols(), p.num_variables());
  EXPECT_EQ(e.kinks.terms.size(), static_cast<size_t>(2 * model.joint_count * 59));
}

}  // namespace
}  // namespace cyclopt::walker
