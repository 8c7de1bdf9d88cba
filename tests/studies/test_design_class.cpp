// The rules that recognise degenerate foot designs (studies/design_class.hpp), on constructed
// gaits: a rolling walk, heel walking, a wheel and two stilts (a fast, short step; a foot without
// area), and on evaluated ones: a gait that exists only on its grid, a resolved one. Each case
// must land in its class and only there.
#include "cyclopt/studies/design_class.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/walker/gait_problem.hpp"
#include "cyclopt/walker/starting_gait.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace cyclopt;
using namespace cyclopt::studies;

namespace {

// A step of period `period` and length `step` whose stance foot angle (minus theta_F,0) goes
// linearly from a to b, with the hip at `hip(s, ankle_x)` for s in [0, 1].
template <class Hip>
walker::PeriodicGait<double> constructed_gait(const walker::WalkerModel<double>& m, double a, double b, double period,
                                              double step, Hip hip) {
  const int n = 41;
  walker::PeriodicGait<double> g;
  g.real = true;
  g.step_length = step;
  g.step_period = period;
  g.trajectory.stance_foot_angle.resize(n);
  g.trajectory.hip.resize(2, n);
  for (int j = 0; j < n; ++j) {
    const double s = j / double(n - 1);
    const double theta = a + s * (b - a);
    g.trajectory.stance_foot_angle(j) = theta + m.foot_zero_angle;
    const double ankle = foot::ankle_position(foot::rolling_contact(m.foot, theta))(0);
    g.trajectory.hip(0, j) = hip(s, ankle);
    g.trajectory.hip(1, j) = 0.9;
  }
  return g;
}

walker::WalkerModel<double> p2() { return walker::make_walker_model(foot::foot_preset("P2-shoes-left-HMT").spec); }

// The first foot angle (minus theta_F,0) from theta_min at which the contact point has travelled
// `fraction` of the way from the heel (theta_min) to the toe (theta_max) on the ground.
double angle_at_contact_fraction(const walker::WalkerModel<double>& m, double fraction) {
  const auto x_c = [&](double t) { return foot::contact_point_on_ground(foot::rolling_contact(m.foot, t)); };
  const double lo = m.foot.theta_min, hi = m.foot.theta_max, heel = x_c(lo), toe = x_c(hi);
  for (int i = 0; i <= 10000; ++i) {
    const double t = lo + (hi - lo) * i / 10000.0;
    if (x_c(t) - heel >= fraction * (toe - heel)) return t;
  }
  return hi;
}

}  // namespace

TEST(DesignClass, RollingWalkIsAdmissible) {
  const auto m = p2();
  // Heel strike, then rolling until the contact point is 70 % of the way to the toe.
  const auto g = constructed_gait(m, angle_at_contact_fraction(m, 0.0), angle_at_contact_fraction(m, 0.7), 0.5, 0.7,
                                  [](double s, double) { return -0.35 + 0.7 * s; });
  const DesignClassification c = classify_design(m, g, g.objective);
  EXPECT_EQ(c.design_class, DesignClass::admissible) << c.reason;
  EXPECT_GT(c.contact_travel, kRollingFraction * c.sole_length) << c.reason;
}

TEST(DesignClass, HeelWalkingDoesNotRoll) {
  const auto m = p2();
  const double lo = m.foot.theta_min;
  const auto g = constructed_gait(m, lo, lo + 0.02, 0.5, 0.7, [](double s, double) { return -0.35 + 0.7 * s; });
  const DesignClassification c = classify_design(m, g, g.objective);
  EXPECT_EQ(c.design_class, DesignClass::no_rolling) << c.reason;
}

TEST(DesignClass, RollingWithStillLegsIsAWheel) {
  const auto m = p2();
  const double lo = m.foot.theta_min, hi = m.foot.theta_max;
  const double a = lo + 0.05 * (hi - lo), b = hi - 0.05 * (hi - lo);
  const double travel = std::abs(foot::ankle_position(foot::rolling_contact(m.foot, b))(0) -
                                 foot::ankle_position(foot::rolling_contact(m.foot, a))(0));
  // The step is the ankle's travel: the hip rides 1 cm ahead of the ankle.
  const auto g = constructed_gait(m, a, b, 0.5, travel, [](double, double ankle) { return ankle + 0.01; });
  const DesignClassification c = classify_design(m, g, g.objective);
  EXPECT_EQ(c.design_class, DesignClass::wheel) << c.reason;
}

TEST(DesignClass, ShortFastStepsAreAStilt) {
  const auto m = p2();
  const double lo = m.foot.theta_min, hi = m.foot.theta_max;
  // The seed's stilt: 60 mm steps at 38 Hz (2.3 m/s).
  const auto g = constructed_gait(m, lo + 0.1 * (hi - lo), hi - 0.1 * (hi - lo), 1.0 / 38.0, 0.06,
                                  [](double s, double) { return -0.03 + 0.06 * s; });
  const DesignClassification c = classify_design(m, g, g.objective);
  EXPECT_EQ(c.design_class, DesignClass::stilt) << c.reason;
  EXPECT_NEAR(c.step_frequency, 38.0, 1e-9);
}

TEST(DesignClass, TheSeedsRho10DesignStepsFastButIsNoStilt) {
  // Table 10.1, rho = 10: the seed's best design. Its optimal gait at 2.3 m/s (the design
  // problem's KKT point from this foot, bench/results/foot_design_bench.txt) rolls from the heel
  // over most of the sole with 0.42 m steps at 5.46 Hz - faster than human walking, far from the
  // stilt's 38 Hz, and admissible.
  foot::FootSpec high;
  high.model = foot::FootModel::hm;
  high.parameters.resize(foot::hm::count);
  high.parameters << 0.1, 0.1095, 0.4, 1e-8, 0.32, 1e-8;  // h_F, l_HA, l_HM, k_H, k_HM, k_M
  high.density = 10.0;
  const auto m = walker::make_walker_model(high);
  const auto g = constructed_gait(m, angle_at_contact_fraction(m, 0.0), angle_at_contact_fraction(m, 0.8), 1.0 / 5.46,
                                  0.42, [](double s, double) { return -0.21 + 0.42 * s; });
  const DesignClassification c = classify_design(m, g, g.objective);
  EXPECT_EQ(c.design_class, DesignClass::admissible) << c.reason;
  EXPECT_GT(c.foot_area, kStiltArea);
}

TEST(DesignClass, AFootWithoutAreaIsAStilt) {
  foot::FootSpec rod;
  rod.model = foot::FootModel::hm;
  rod.parameters.resize(foot::hm::count);
  rod.parameters << 1e-6, 1e-3, 0.3, 1e-8, 1e-8, 1e-8;  // h_F, l_HA, l_HM, k_H, k_HM, k_M: a line
  const auto m = walker::make_walker_model(rod);
  const double lo = m.foot.theta_min, hi = m.foot.theta_max;
  const auto g = constructed_gait(m, lo + 0.1 * (hi - lo), hi - 0.1 * (hi - lo), 0.5, 0.7,
                                  [](double s, double) { return -0.35 + 0.7 * s; });
  const DesignClassification c = classify_design(m, g, g.objective);
  EXPECT_EQ(c.design_class, DesignClass::stilt) << c.reason;
  EXPECT_LT(c.foot_area, kStiltArea);
}

TEST(DesignClass, PointFeetAreNeverDegenerate) {
  const auto m = walker::make_walker_model(foot::foot_preset("point").spec);
  walker::PeriodicGait<double> g;
  g.step_length = 0.06;
  g.step_period = 1.0 / 38.0;
  EXPECT_EQ(classify_design(m, g, g.objective).design_class, DesignClass::admissible);
}

TEST(DesignClass, AGaitThatExistsOnlyOnItsGridIsUnderResolved) {
  // A KKT point of the rho 10 design multistart at 2.3 m/s (2026-12-05; gait re-solved on the
  // design's foot rounded to 4 digits): f_mech 0.0044 on P = 200, 0.18 on 4P, 0.12 on 64P. Its
  // positive work per step (1.1 J) is below the impact loss it must replace (6.5 J).
  foot::FootSpec spec;
  spec.model = foot::FootModel::hmt;
  spec.parameters.resize(foot::hmt::count);
  // h_F, l_HA, l_HM, l_MT, gamma_F, k_H, k_HM, k_MT, k_T
  spec.parameters << 0.1, 0.07804, 0.1327, 0.1, 0.2228, 1e-8, 0.5, 0.000391, 1e-8;
  spec.density = 10.0;
  const auto m = walker::make_walker_model(spec);
  const walker::GaitProblem problem(m, {walker::Objective::mechanical, 2.3, walker::Quadrature::trapezoid, {}});
  Eigen::VectorXd x(30);
  x << 3.596003020355752, 3.5375649980613377, 0.09136159024704213, 0.3734906300940708, -0.10139557944558222,
      0.6175928661491491, 3.545383523358399, 3.5728004288243147, 0.2331775630070588, 0.2341897488902956,
      -0.0283737170624951, -0.4030637840394538, 3.579449504417742, 3.5579127317412893, 0.22624956734892834,
      0.2088776579599218, 0.16241720351930228, 0.22060703810029103, 3.5616616126002723, 3.573525120013537,
      0.3057915414524474, 0.08385684116399678, 0.2332574268791232, -0.36676463308874063, 3.5694786777314627,
      3.561537375971284, 0.3387524213798205, 0.03950297236963083, 4.047751004729388, 2.9093644801521172;
  const walker::PeriodicGait<double> g = problem.gait_at(x);
  ASSERT_TRUE(g.real) << g.failure;
  EXPECT_NEAR(g.f_mech, 0.00443, 1e-4);
  EXPECT_LT(g.f_mech * m.total_mass * 9.81 * g.step_length, g.impact_energy_loss) << "not the artefact any more";
  const double refined = problem.refined_objective(x, kResolutionFactor);
  EXPECT_GT(refined, 10 * g.f_mech);
  const DesignClassification c = classify_design(m, g, refined);
  EXPECT_EQ(c.design_class, DesignClass::under_resolved) << c.reason;
  EXPECT_EQ(c.refined_objective, refined);
  // Without a gait on the finer grid it is under-resolved too.
  EXPECT_EQ(classify_design(m, g, std::nan("")).design_class, DesignClass::under_resolved);
}

TEST(DesignClass, AResolvedGaitKeepsItsObjectiveOnTheFinerGrid) {
  const auto m = p2();
  const walker::GaitProblem problem(m, {walker::Objective::mechanical, 1.3, walker::Quadrature::trapezoid, {}});
  const Eigen::VectorXd x = walker::gait_start(walker::GaitEvaluator(m), 1.3, {}).x;
  const walker::PeriodicGait<double> g = problem.gait_at(x);
  ASSERT_TRUE(g.real) << g.failure;
  const double refined = problem.refined_objective(x, kResolutionFactor);
  EXPECT_NEAR(refined, g.f_mech, 0.01 * g.f_mech);
  EXPECT_NE(classify_design(m, g, refined).design_class, DesignClass::under_resolved);
  EXPECT_EQ(problem.refined_objective(x, 1), g.objective);
  EXPECT_THROW(problem.refined_objective(x, 0), std::invalid_argument);
}
