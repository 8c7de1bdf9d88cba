// A sweep's closure of its envelope and its searches per seed (speed_sweep.hpp, issue 21 items 3
// and 4), on the point-foot case of test_speed_sweep_recovery (0.6-0.9 m/s, seeded at 0.6 m/s, two
// starts):
// - closed: after the sweep no solve from a neighbouring speed's best point beats a speed's best
//   point by more than closure.min_improvement - checked here by solves of the test's own;
// - seeds (1.0-1.2 m/s, closure off): each seed's search is the same computation as a sweep with that seed alone (bitwise:
//   the searches see only their own curves), the envelope is the best over the searches, the
//   spread per speed is (max - min) / min of the searches' own objectives, curve ids do not overlap.
#include "cyclopt/studies/speed_sweep.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/nlp/solve.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

using namespace cyclopt;
using namespace cyclopt::continuation;
using namespace cyclopt::studies;

namespace {

const walker::GaitProblemOptions kProblem{walker::Objective::mechanical, 0.6, walker::Quadrature::trapezoid, {}};

SpeedSweepOptions small_case() {
  SpeedSweepOptions o;
  o.speeds = {0.6, 0.7, 0.8, 0.9};
  o.seed_speeds = {0.6};
  o.starts = 2;
  return o;
}

const walker::WalkerModel<double>& point_feet() {
  static const walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset("point").spec);
  return model;
}

}  // namespace

TEST(SweepClosure, NoNeighbourStartBeatsAClosedEnvelope) {
  const SpeedSweepOptions o = small_case();
  const SpeedSweepResult r = speed_sweep(point_feet(), kProblem, o);
  std::printf("%s, %d solves\n", describe(r.closure).c_str(), r.closure.solves);
  ASSERT_TRUE(r.closure.closed) << r.closure.reason;
  EXPECT_GE(r.closure.passes, 1);
  EXPECT_EQ(describe(r.closure).rfind("closed after ", 0), 0u);
  for (std::size_t i = 0; i < r.best.size(); ++i) {
    ASSERT_TRUE(r.best[i].found) << r.best[i].speed;
    for (std::size_t j : {i - 1, i + 1}) {
      if (j >= r.best.size()) continue;
      walker::GaitProblemOptions at = kProblem;
      at.speed = r.best[i].speed;
      walker::GaitProblem p(point_feet(), at);
      nlp::SolverOptions so = nlp::seed_table_6_2_options();
      so.sqp.difference_hessian = true;
      const nlp::SolverSummary s = nlp::solve(p, so, r.best[j].point.x);
      if (!s.success()) continue;  // no optimum from there: nothing to beat
      const double f = r.best[i].point.objective;
      EXPECT_GE(s.objective, f - o.closure.min_improvement * f)
          << "from " << r.best[j].speed << " m/s a better point at " << r.best[i].speed << " m/s";
    }
  }
}

// Seeds on a grid that continuation covers without recovery (1.0-1.2 m/s), closure off: cheaper.
SpeedSweepOptions seeds_case() {
  SpeedSweepOptions o;
  o.speeds = {1.0, 1.1, 1.2};
  o.seed_speeds = {1.0};
  o.starts = 2;
  o.closure.enabled = false;
  return o;
}

TEST(SweepSeeds, EachSeedSearchesAloneAndTheEnvelopeIsTheirBest) {
  SpeedSweepOptions alone = seeds_case();
  alone.seeds = {7};
  const SpeedSweepResult second = speed_sweep(point_feet(), kProblem, alone);
  alone.seeds = {1};
  const int first_curves = speed_sweep(point_feet(), kProblem, alone).curves;
  SpeedSweepOptions o = seeds_case();
  o.seeds = {1, 7};
  // max_curves bounds each search (not their sum): with exactly the curves each needs alone, the
  // second search is still the sweep of its seed alone.
  o.max_curves = std::max(first_curves, second.curves);
  std::set<int> reported_curves;
  const SpeedSweepResult r = speed_sweep(point_feet(), kProblem, o, [&](const CurvePoint& p) {
    reported_curves.insert(p.curve_id);
    return true;
  });
  ASSERT_EQ(r.searches.size(), 2u);
  EXPECT_EQ(r.searches[0].seed, 1u);
  EXPECT_EQ(r.searches[1].seed, 7u);
  EXPECT_EQ(r.searches[0].first_curve, 0);
  EXPECT_EQ(r.searches[1].first_curve, r.searches[0].curves);  // ids run on
  EXPECT_EQ(r.curves, r.searches[0].curves + r.searches[1].curves);
  EXPECT_LE(static_cast<int>(reported_curves.size()), r.curves);
  EXPECT_LT(*reported_curves.rbegin(), r.curves);

  EXPECT_EQ(r.closure.reason, "seed 1 of 2: closure off");
  EXPECT_EQ(r.closure.solves, 0);
  ASSERT_EQ(second.best.size(), r.best.size());
  for (std::size_t i = 0; i < r.best.size(); ++i) {
    const BestPoint& a = r.searches[1].best[i];
    const BestPoint& b = second.best[i];
    ASSERT_EQ(a.found, b.found) << i;
    if (!a.found) continue;
    EXPECT_EQ(a.point.objective, b.point.objective) << "seed 7's search differs from a sweep with seed 7 alone at " << a.speed;
    EXPECT_EQ(a.point.x, b.point.x) << i;
    EXPECT_EQ(a.point.curve_id - r.searches[1].first_curve, b.point.curve_id) << i;
    EXPECT_EQ(a.seed, 7u);
  }
  for (std::size_t i = 0; i < r.best.size(); ++i) {
    std::vector<double> f;
    for (const SeedSearch& s : r.searches)
      if (s.best[i].found) f.push_back(s.best[i].point.objective);
    ASSERT_EQ(f.size(), 2u) << i;
    const double lo = *std::min_element(f.begin(), f.end()), hi = *std::max_element(f.begin(), f.end());
    ASSERT_TRUE(r.best[i].found);
    EXPECT_EQ(r.best[i].point.objective, lo) << i;
    EXPECT_DOUBLE_EQ(r.seed_spread[i], (hi - lo) / lo) << i;
    std::printf("%.1f m/s: seeds %.6f %.6f, spread %.2e, best from seed %llu\n", r.best[i].speed, f[0], f[1], r.seed_spread[i],
                static_cast<unsigned long long>(r.best[i].seed));
  }
}

TEST(SweepSeeds, RepeatedOrNoSeedsAreRejected) {
  SpeedSweepOptions o = small_case();
  o.seeds = {};
  EXPECT_THROW(speed_sweep(point_feet(), kProblem, o), std::invalid_argument);
  o.seeds = {3, 3};
  EXPECT_THROW(speed_sweep(point_feet(), kProblem, o), std::invalid_argument);
  o.seeds = {1};
  o.closure.max_passes = 0;
  EXPECT_THROW(speed_sweep(point_feet(), kProblem, o), std::invalid_argument);
}
