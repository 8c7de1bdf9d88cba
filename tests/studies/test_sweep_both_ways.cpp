// The upward and the downward run from a new point computed at once on a spare core
// (speed_sweep.hpp, Sweep::continue_both_ways): with a core assumed spare (SpareCoreRule::always)
// the sweep reports the same points in the same order with the same curve ids, and holds the same
// runs bit for bit, as with the runs one after the other (never); a job stopped inside the
// downward run sees the same points before it stops.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/nlp/spare_core.hpp"
#include "cyclopt/studies/speed_sweep.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
#include <string>
#include <vector>

using namespace cyclopt;
using namespace cyclopt::studies;

namespace {

// What on_point saw.
struct Reported {
  double parameter = 0.0;
  int curve_id = 0;
  double objective = 0.0;
  Eigen::VectorXd x;
};

struct Sweep {
  SpeedSweepResult result;
  std::vector<Reported> reported;
  bool both_ways = false;  // a progress report named two runs at once
};

// The sweep of the recovery and resume tests (point feet, R1-R3 with runs of their own), seeded
// inside the grid so that its first curve is continued both ways; stopped after `stop_after` points.
Sweep sweep(nlp::SpareCoreRule rule, int stop_after = std::numeric_limits<int>::max()) {
  static const walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset("point").spec);
  const walker::GaitProblemOptions problem{walker::Objective::mechanical, 0.7, walker::Quadrature::trapezoid, {}};
  SpeedSweepOptions o;
  o.speeds = {0.6, 0.7, 0.8, 0.9};
  o.seed_speeds = {0.7};
  o.starts = 2;
  Sweep s;
  class Observer final : public SpeedSweepObserver {
   public:
    Observer(Sweep& s, int stop_after) : s_(s), stop_after_(stop_after) {}
    bool on_point(const CurvePoint& p) override {
      s_.reported.push_back({p.parameter, p.curve_id, p.objective, p.x});
      return static_cast<int>(s_.reported.size()) < stop_after_;
    }
    void on_progress(const SweepProgress& p) override {
      s_.both_ways = s_.both_ways || p.detail.find("upwards and downwards") != std::string::npos;
    }

   private:
    Sweep& s_;
    const int stop_after_;
  } observer(s, stop_after);
  nlp::set_spare_core_rule(rule);
  s.result = speed_sweep(model, problem, o, observer);
  nlp::set_spare_core_rule(nlp::SpareCoreRule::measured);
  return s;
}

void expect_same_reports(const std::vector<Reported>& a, const std::vector<Reported>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].parameter, b[k].parameter) << k;
    EXPECT_EQ(a[k].curve_id, b[k].curve_id) << k;
    EXPECT_EQ(a[k].objective, b[k].objective) << k;
    EXPECT_EQ(a[k].x, b[k].x) << k;
  }
}

}  // namespace

TEST(SweepBothWays, RunsComputedAtOnceGiveTheSweepOfOneThread) {
  const Sweep one = sweep(nlp::SpareCoreRule::never), both = sweep(nlp::SpareCoreRule::always);
  EXPECT_FALSE(one.both_ways);
  EXPECT_TRUE(both.both_ways);
  expect_same_reports(one.reported, both.reported);
  ASSERT_EQ(one.result.runs.size(), both.result.runs.size());
  for (std::size_t r = 0; r < one.result.runs.size(); ++r) {
    const continuation::ContinuationResult &a = one.result.runs[r], &b = both.result.runs[r];
    EXPECT_EQ(a.message, b.message) << r;
    EXPECT_EQ(a.next_curve_id, b.next_curve_id) << r;
    EXPECT_EQ(a.jumps.size(), b.jumps.size()) << r;
    ASSERT_EQ(a.points.size(), b.points.size()) << r;
    for (std::size_t k = 0; k < a.points.size(); ++k) {
      EXPECT_EQ(a.points[k].curve_id, b.points[k].curve_id) << r << " " << k;
      EXPECT_EQ(a.points[k].x, b.points[k].x) << r << " " << k;
    }
  }
  int jumps = 0;
  for (const continuation::ContinuationResult& run : both.result.runs) jumps += static_cast<int>(run.jumps.size());
  std::printf("%zu runs, %d curves, %d jumps, %zu points reported\n", both.result.runs.size(), both.result.curves, jumps,
              both.reported.size());
  EXPECT_EQ(one.result.curves, both.result.curves);
  EXPECT_EQ(one.result.computed_runs, both.result.computed_runs);
  for (std::size_t i = 0; i < one.result.best.size(); ++i) {
    ASSERT_EQ(one.result.best[i].found, both.result.best[i].found) << i;
    if (one.result.best[i].found) {
      EXPECT_EQ(one.result.best[i].point.x, both.result.best[i].point.x) << i;
    }
  }
}

TEST(SweepBothWays, AStopInsideTheDownwardRunSeesTheSamePoints) {
  const Sweep whole = sweep(nlp::SpareCoreRule::never);
  // The second point below the seed speed: inside the first downward run.
  int below = 0, stop_after = 0;
  for (std::size_t k = 0; k < whole.reported.size() && stop_after == 0; ++k)
    if (whole.reported[k].parameter < 0.7 && ++below == 2) stop_after = static_cast<int>(k) + 1;
  ASSERT_GT(stop_after, 0) << "no downward run reported two points";
  const Sweep one = sweep(nlp::SpareCoreRule::never, stop_after), both = sweep(nlp::SpareCoreRule::always, stop_after);
  EXPECT_EQ(static_cast<int>(one.reported.size()), stop_after);
  expect_same_reports(one.reported, both.reported);
  EXPECT_EQ(one.result.runs.size(), both.result.runs.size());
}
