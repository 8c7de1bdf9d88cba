// The foot comparison (studies/foot_comparison.hpp): savings and the best-foot envelope from
// per-speed f_mech values worked out by hand, including speeds a foot or the reference missed;
// and one real comparison of point feet against the P1 barefoot HM foot at two speeds whose
// summary must agree with the gaits of its own best points.
#include "cyclopt/studies/foot_comparison.hpp"
#include "cyclopt/foot/foot_presets.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

using namespace cyclopt;
using namespace cyclopt::studies;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

FootSweepSummary summary(const std::string& name, std::vector<double> f) {
  FootSweepSummary s;
  s.name = name;
  s.f_mech = std::move(f);
  for (double v : s.f_mech) s.speeds_found += std::isfinite(v);
  return s;
}

}  // namespace

TEST(FootComparison, SavingsAndEnvelopeOverTheSharedSpeeds) {
  // Reference (point feet) misses the last speed; foot A misses the first.
  const FootComparisonResult r = summarise_feet({0.5, 1.0, 1.5, 2.0},
                                                {summary("point", {0.2, 0.4, 0.6, kNaN}),
                                                 summary("A", {kNaN, 0.1, 0.3, 0.2}),
                                                 summary("B", {0.1, 0.2, 0.2, 0.5})},
                                                0);
  EXPECT_DOUBLE_EQ(r.feet[0].saving, 0.0);
  EXPECT_EQ(r.feet[0].common_speeds, 3);
  EXPECT_NEAR(r.feet[0].mean_f_mech, 0.4, 1e-15);
  // A: speeds 1.0 and 1.5 shared: mean 0.2 against 0.5.
  EXPECT_EQ(r.feet[1].common_speeds, 2);
  EXPECT_NEAR(r.feet[1].mean_f_mech, 0.2, 1e-15);
  EXPECT_NEAR(r.feet[1].saving, 1.0 - 0.2 / 0.5, 1e-15);
  // B: speeds 0.5-1.5: mean 0.5/3 against 0.4.
  EXPECT_EQ(r.feet[2].common_speeds, 3);
  EXPECT_NEAR(r.feet[2].saving, 1.0 - (0.5 / 3) / 0.4, 1e-15);
  // Best per speed among A and B (never the reference), NaN-aware.
  EXPECT_EQ(r.best_foot, (std::vector<int>{2, 1, 2, 1}));
  EXPECT_NEAR(r.envelope_f_mech[2], 0.2, 1e-15);
  EXPECT_EQ(r.envelope_common_speeds, 3);
  EXPECT_NEAR(r.envelope_saving, 1.0 - (0.1 + 0.1 + 0.2) / 3 / 0.4, 1e-15);
  // B reaches every speed the reference reaches, A does not: B is the best mean foot although
  // A's saving (60 %) is larger than B's (58 %).
  EXPECT_GT(r.feet[1].saving, r.feet[2].saving);
  EXPECT_EQ(r.best_mean_foot, 2);
  EXPECT_THROW(summarise_feet({0.5}, {summary("point", {0.2})}, 1), std::invalid_argument);
}

// Three seeds (SpeedSweepOptions::seeds): per seed, the saving of that seed's search of a foot
// against that seed's search of the reference; the ranking by the feet's own (best-over-seeds)
// saving; order_held where a foot beat the next-ranked one with every seed.
TEST(FootComparison, TheRankingSaysWhereEverySeedAgrees) {
  auto seeded = [](const std::string& name, std::vector<std::vector<double>> per_seed) {
    std::vector<double> best = per_seed.front();
    for (const auto& f : per_seed)
      for (std::size_t i = 0; i < best.size(); ++i) best[i] = std::min(best[i], f[i]);
    FootSweepSummary s = summary(name, best);
    s.seeds = {1, 2, 3};
    s.seed_f_mech = std::move(per_seed);
    return s;
  };
  const FootComparisonResult r = summarise_feet(
      {1.0, 2.0},
      {seeded("point", {{0.4, 0.6}, {0.4, 0.6}, {0.4, 0.6}}),
       seeded("A", {{0.10, 0.30}, {0.10, 0.30}, {0.10, 0.30}}),     // saving 60 % with every seed
       seeded("B", {{0.20, 0.30}, {0.21, 0.30}, {0.11, 0.30}}),     // 50, 49, 59 %; best of the seeds 59 %
       seeded("C", {{0.19, 0.30}, {0.19, 0.30}, {0.19, 0.30}})},    // 51 %: above B with seeds 1 and 2
      0);
  EXPECT_EQ(r.ranking, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(r.feet[1].rank, 0);
  EXPECT_EQ(r.feet[0].rank, -1);
  ASSERT_EQ(r.feet[2].seed_savings.size(), 3u);
  EXPECT_NEAR(r.feet[2].seed_savings[0], 1.0 - 0.25 / 0.5, 1e-15);
  EXPECT_NEAR(r.feet[2].seed_savings[1], 1.0 - 0.255 / 0.5, 1e-15);
  EXPECT_NEAR(r.feet[2].saving, 1.0 - 0.205 / 0.5, 1e-15);  // the best of the seeds at each speed
  EXPECT_NEAR(spread(r.feet[2].seed_savings), (1.0 - 0.205 / 0.5) - (1.0 - 0.255 / 0.5), 1e-15);
  ASSERT_TRUE(r.feet[1].order_held.has_value());
  EXPECT_TRUE(*r.feet[1].order_held);   // A above B with every seed
  ASSERT_TRUE(r.feet[2].order_held.has_value());
  EXPECT_FALSE(*r.feet[2].order_held);  // B above C with seed 3 only
  EXPECT_FALSE(r.feet[3].order_held.has_value());  // the last
  EXPECT_FALSE(r.feet[0].order_held.has_value());  // the reference
  // One seed: no verdict.
  const FootComparisonResult one = summarise_feet({1.0}, {summary("point", {0.4}), summary("A", {0.1}), summary("B", {0.2})}, 0);
  EXPECT_FALSE(one.feet[1].order_held.has_value());
  EXPECT_TRUE(std::isnan(spread(one.feet[1].seed_savings)));
}

TEST(FootComparison, PointFeetAgainstARollingFootAtTwoSpeeds) {
  const walker::GaitProblemOptions problem{walker::Objective::mechanical, 1.0, walker::Quadrature::trapezoid, {}};
  walker::WalkingConstants coarse;
  coarse.points = 100;  // P of eq. (5.93): half the default, to keep the test short
  SpeedSweepOptions o;
  o.speeds = {1.0, 1.1};
  o.seed_speeds = {1.0};
  o.starts = 2;
  o.scale = 0.02;
  std::vector<FootSweepSummary> feet;
  for (const char* name : {"point", "P1-barefoot-left-HM-SG"}) {
    int points = 0;
    feet.push_back(sweep_foot(name, walker::make_walker_model(foot::foot_preset(name).spec, coarse), problem, o,
                              [&](const CurvePoint&) { return ++points > 0; }));
    EXPECT_GT(points, 0) << name;
    EXPECT_FALSE(feet.back().stopped) << name;
  }
  const FootComparisonResult r = summarise_feet(o.speeds, feet, 0);
  ASSERT_EQ(r.feet.size(), 2u);
  for (const FootSweepSummary& s : r.feet) {
    std::printf("%s: f_mech %.5f %.5f, mean %.5f, saving %.3f, %.1f s\n", s.name.c_str(), s.f_mech[0], s.f_mech[1],
                s.mean_f_mech, s.saving, s.seconds);
    ASSERT_EQ(s.speeds_found, 2) << s.name;
    // The objective is f_mech: the summary's value is the optimiser's objective at the point.
    for (std::size_t i = 0; i < 2; ++i) EXPECT_NEAR(s.f_mech[i], s.best[i].point.objective, 1e-9) << s.name;
  }
  const double expected = 1.0 - (r.feet[1].f_mech[0] + r.feet[1].f_mech[1]) / (r.feet[0].f_mech[0] + r.feet[0].f_mech[1]);
  EXPECT_NEAR(r.feet[1].saving, expected, 1e-12);
  EXPECT_EQ(r.best_foot, (std::vector<int>{1, 1}));  // the only compared foot
  EXPECT_EQ(r.best_mean_foot, 1);
  // Rolling feet walk more cheaply than point feet (seed 001 Fig. 9.19a).
  EXPECT_GT(r.feet[1].saving, 0.0);
}
