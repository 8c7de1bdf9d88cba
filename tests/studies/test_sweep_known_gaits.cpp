// SpeedSweepOptions::known_gaits (speed_sweep.hpp): a gait the caller solved already (the foot
// design's optimum, foot_design.hpp step 3) is solved from and continued before the seed
// multistarts, so the sweep's curve through that speed is the known optimum's.
#include "cyclopt/studies/speed_sweep.hpp"
#include "cyclopt/foot/foot_presets.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace cyclopt;
using namespace cyclopt::studies;

namespace {

const walker::WalkerModel<double>& point_feet() {
  static const walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset("point").spec);
  return model;
}

const walker::GaitProblemOptions kProblem{walker::Objective::mechanical, 0.6, walker::Quadrature::trapezoid, {}};

SpeedSweepOptions two_speeds(double seed_speed) {
  SpeedSweepOptions o;
  o.speeds = {0.6, 0.7};
  o.seed_speeds = {seed_speed};
  o.starts = 1;
  o.recover = false;
  return o;
}

}  // namespace

TEST(SweepKnownGaits, ContinuesTheKnownGaitsCurveFirst) {
  // The known optimum at 0.6 m/s, from a sweep seeded there.
  const SpeedSweepResult reference = speed_sweep(point_feet(), kProblem, two_speeds(0.6));
  ASSERT_TRUE(reference.best[0].found) << reference.best[0].reason;
  const CurvePoint& known = reference.best[0].point;

  // Seeded at 0.7 m/s only, with the known gait at 0.6 m/s.
  SpeedSweepOptions o = two_speeds(0.7);
  o.known_gaits = {{0.6, known.x}};
  const SpeedSweepResult r = speed_sweep(point_feet(), kProblem, o);
  ASSERT_GE(r.curves, 1);
  EXPECT_EQ(r.origins.front().step, SweepStep::known_gait);
  EXPECT_DOUBLE_EQ(r.origins.front().speed, 0.6);
  ASSERT_FALSE(r.runs.empty());
  EXPECT_EQ(r.runs.front().points.front().curve_id, 0);
  EXPECT_NEAR(r.runs.front().points.front().objective, known.objective, 1e-8 * known.objective);
  for (const BestPoint& b : r.best) EXPECT_TRUE(b.found) << b.speed << " m/s: " << b.reason;
  // The selected point at 0.6 m/s is the known optimum or better.
  EXPECT_LE(r.best[0].point.objective, known.objective * (1 + 1e-8));
  EXPECT_STREQ(to_string(SweepStep::known_gait), "solve from a known gait");
}

TEST(SweepKnownGaits, RefusesAKnownGaitOffTheGridOrOfTheWrongSize) {
  SpeedSweepOptions o = two_speeds(0.7);
  o.known_gaits = {{0.65, Eigen::VectorXd::Zero(20)}};
  try {
    speed_sweep(point_feet(), kProblem, o);
    FAIL() << "a known gait at 0.65 m/s was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("known_gaits: speed 0.65"), std::string::npos) << e.what();
  }
  o.known_gaits = {{0.6, Eigen::VectorXd::Zero(3)}};
  EXPECT_THROW(speed_sweep(point_feet(), kProblem, o), std::invalid_argument);
}
