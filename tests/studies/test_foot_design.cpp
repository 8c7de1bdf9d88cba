// The foot-design study's option checks (studies/foot_design.hpp): each bad option is refused
// before anything is solved, naming the option.
#include "cyclopt/studies/foot_design.hpp"
#include "cyclopt/foot/convexity_constraints.hpp"
#include "cyclopt/foot/foot_presets.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace cyclopt;
using namespace cyclopt::studies;

namespace {

std::string refusal(const foot::FootSpec& start, const FootDesignOptions& o) {
  try {
    design_feet(start, {}, o);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

FootDesignOptions small() {
  FootDesignOptions o;
  o.densities = {10};
  o.sweep.speeds = {2.2, 2.3};
  o.design_speed = 2.3;
  return o;
}

const foot::FootSpec& p2() { return foot::foot_preset("P2-shoes-left-HMT").spec; }

}  // namespace

TEST(FootDesign, RefusesBadOptionsNamingThem) {
  FootDesignOptions o = small();
  o.densities = {10, -5};
  EXPECT_EQ(refusal(p2(), o).rfind("densities:", 0), 0u) << refusal(p2(), o);
  o = small();
  o.design_speed = 1.0;
  EXPECT_EQ(refusal(p2(), o).rfind("design_speed:", 0), 0u) << refusal(p2(), o);
  o = small();
  o.free_parameters = {"l_HM", "k_X"};
  EXPECT_NE(refusal(p2(), o).find("free_parameters: 'k_X'"), std::string::npos) << refusal(p2(), o);
  o = small();
  o.starts = 0;
  EXPECT_EQ(refusal(p2(), o).rfind("starts:", 0), 0u);
  o = small();
  o.foot_scale = -1;
  EXPECT_EQ(refusal(p2(), o).rfind("foot_scale:", 0), 0u) << refusal(p2(), o);
  EXPECT_EQ(refusal(foot::foot_preset("point").spec, small()).rfind("foot:", 0), 0u);
}

TEST(FootDesign, RefusesBoundsThatExcludeTheStartFootInAFixedParameter) {
  // P2's h_F is 106.5 mm, above h_F,max = 100 mm: with h_F free it is moved onto the bound, with
  // h_F fixed the bounds exclude the start foot.
  FootDesignOptions o = small();
  o.free_parameters = {"l_HM", "k_HM"};
  EXPECT_EQ(refusal(p2(), o).rfind("design_bounds:", 0), 0u) << refusal(p2(), o);
}

TEST(FootDesign, DrawnStartFeetVaryTheFreeParametersWithinBoundsAndConvexity) {
  foot::FootSpec start = p2();
  const foot::DesignBounds bounds;
  const std::vector<std::string> all{"h_F", "l_HA", "l_HM", "l_MT", "gamma_F", "k_H", "k_HM", "k_MT", "k_T"};
  start.parameters = foot::project_into_design_bounds(start.model, start.parameters, bounds, all);
  const auto layout = foot::parameter_layout(start.model);
  const foot::LinearInequalities convex = foot::convexity_constraints(start.model);
  std::mt19937_64 rng(7);
  double k_HM_min = 1e9, k_HM_max = 0;
  for (int draw = 0; draw < 200; ++draw) {
    const foot::FootParameters<double> p = draw_design_foot(start, all, bounds, 1.0, rng);
    EXPECT_TRUE(foot::violated_design_bounds(start.model, p, bounds, 1e-12).empty()) << p.transpose();
    EXPECT_TRUE(((convex.A * p + convex.b).array() >= 0.0).all()) << p.transpose();
    EXPECT_GT(foot::toe_convexity_margin(p), 0.0) << p.transpose();
    for (std::size_t k = 0; k < layout.size(); ++k) {
      EXPECT_GE(p[static_cast<Eigen::Index>(k)], layout[k].min) << layout[k].name;
      EXPECT_LE(p[static_cast<Eigen::Index>(k)], layout[k].max) << layout[k].name;
    }
    k_HM_min = std::min(k_HM_min, p[foot::hmt::k_HM]);
    k_HM_max = std::max(k_HM_max, p[foot::hmt::k_HM]);
  }
  // exp(N(0,1)) spreads k_HM = 0.054 over more than a factor 5 (the seed's rho 10 design has 0.32).
  EXPECT_GT(k_HM_max / k_HM_min, 5.0);
  // Only the free parameters move; scale 0 keeps the start foot.
  const foot::FootParameters<double> some = draw_design_foot(start, {"k_HM"}, bounds, 1.0, rng);
  for (Eigen::Index i = 0; i < some.size(); ++i) {
    if (i != foot::hmt::k_HM) {
      EXPECT_EQ(some[i], start.parameters[i]) << layout[static_cast<std::size_t>(i)].name;
    }
  }
  EXPECT_EQ(draw_design_foot(start, all, bounds, 0.0, rng), start.parameters);
}

TEST(FootDesign, DefaultDesignHoldsTheCornerCurvaturesAsTheSeedDoes) {
  // Tables 10.1 and 10.2: every design of the seed has k_H = k_T = 1e-8, the fits' fixed value
  // (4.13, 4.18); the other parameters are designed.
  EXPECT_EQ(default_design_parameters(foot::FootModel::hmt),
            (std::vector<std::string>{"h_F", "l_HA", "l_HM", "l_MT", "gamma_F", "k_HM", "k_MT"}));
  EXPECT_EQ(default_design_parameters(foot::FootModel::hm), (std::vector<std::string>{"h_F", "l_HA", "l_HM", "k_HM"}));
}

TEST(FootDesign, TheAnswerIsTheDesignThatReachesMoreSpeedsThenTheCheaperOne) {
  const double nan = std::nan("");
  const auto sweep = [](std::vector<double> f) {
    FootSweepSummary s;
    s.f_mech = std::move(f);
    s.speeds_found = static_cast<int>(std::count_if(s.f_mech.begin(), s.f_mech.end(), [](double x) { return std::isfinite(x); }));
    return s;
  };
  // Equal reach: the lower mean wins; a tie keeps the design (the seed's choice).
  EXPECT_EQ(better_design(sweep({0.005, 0.010, 0.020}), sweep({0.001, 0.010, 0.021})), DesignAnswer::low_speed_design);
  EXPECT_EQ(better_design(sweep({0.005, 0.010, 0.020}), sweep({0.007, 0.010, 0.020})), DesignAnswer::design);
  EXPECT_EQ(better_design(sweep({0.005, 0.010, 0.020}), sweep({0.005, 0.010, 0.020})), DesignAnswer::design);
  // More speeds win whatever the mean (run D's low-speed design: cheaper, but 0.4 m/s missing).
  EXPECT_EQ(better_design(sweep({0.005, 0.010, 0.020}), sweep({0.001, nan, 0.010})), DesignAnswer::design);
  EXPECT_EQ(better_design(sweep({0.001, nan, 0.010}), sweep({0.005, 0.010, 0.020})), DesignAnswer::low_speed_design);
  // Equal reach on different speeds: compared over the speeds both reached.
  EXPECT_EQ(better_design(sweep({nan, 0.010, 0.020}), sweep({0.001, nan, 0.021})), DesignAnswer::design);
  // add_savings sets the answer, and the answer's savings are its sweep's.
  DensityDesign d;
  d.high = sweep({0.005, 0.010, 0.020});
  d.low = sweep({0.001, 0.010, 0.020});
  const std::vector<double> speeds{0.3, 0.4, 0.5};
  add_savings(d, speeds, sweep({0.010, 0.020, 0.030}), sweep({0.020, 0.040, 0.060}));
  EXPECT_EQ(d.answer, DesignAnswer::low_speed_design);
  EXPECT_EQ(&d.answer_sweep(), &d.low);
  EXPECT_NEAR(d.answer_saving_vs_start(), 1 - 0.031 / 0.060, 1e-12);
  EXPECT_NEAR(d.answer_saving_vs_point(), 1 - 0.031 / 0.120, 1e-12);
  EXPECT_NEAR(d.saving_vs_start, 1 - 0.035 / 0.060, 1e-12);
  EXPECT_STREQ(to_string(d.answer), "low-speed design");
}
