// The rules that recognise degenerate foot designs (studies/design_class.hpp), on constructed
// gaits: a rolling walk, heel walking, a wheel and two stilts (a fast, short step; a foot without
// area). Each constructed case must land in its class and only there.
#include "cyclopt/studies/design_class.hpp"
#include "cyclopt/foot/foot_presets.hpp"

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
  const DesignClassification c = classify_design(m, g);
  EXPECT_EQ(c.design_class, DesignClass::admissible) << c.reason;
  EXPECT_GT(c.contact_travel, kRollingFraction * c.sole_length) << c.reason;
}

TEST(DesignClass, HeelWalkingDoesNotRoll) {
  const auto m = p2();
  const double lo = m.foot.theta_min;
  const auto g = constructed_gait(m, lo, lo + 0.02, 0.5, 0.7, [](double s, double) { return -0.35 + 0.7 * s; });
  const DesignClassification c = classify_design(m, g);
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
  const DesignClassification c = classify_design(m, g);
  EXPECT_EQ(c.design_class, DesignClass::wheel) << c.reason;
}

TEST(DesignClass, ShortFastStepsAreAStilt) {
  const auto m = p2();
  const double lo = m.foot.theta_min, hi = m.foot.theta_max;
  // The seed's stilt: 60 mm steps at 38 Hz (2.3 m/s).
  const auto g = constructed_gait(m, lo + 0.1 * (hi - lo), hi - 0.1 * (hi - lo), 1.0 / 38.0, 0.06,
                                  [](double s, double) { return -0.03 + 0.06 * s; });
  const DesignClassification c = classify_design(m, g);
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
  const DesignClassification c = classify_design(m, g);
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
  const DesignClassification c = classify_design(m, g);
  EXPECT_EQ(c.design_class, DesignClass::stilt) << c.reason;
  EXPECT_LT(c.foot_area, kStiltArea);
}

TEST(DesignClass, PointFeetAreNeverDegenerate) {
  const auto m = walker::make_walker_model(foot::foot_preset("point").spec);
  walker::PeriodicGait<double> g;
  g.step_length = 0.06;
  g.step_period = 1.0 / 38.0;
  EXPECT_EQ(classify_design(m, g).design_class, DesignClass::admissible);
}
