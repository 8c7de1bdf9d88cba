// The fits of seed 001 section 4.2 against synthetic ground truth: exact Jacobian (against
// central differences), the circle fit, and recovery of the generating foot without noise
// (issue 20, acceptance 2).
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot_fit/ankle_track.hpp"
#include "cyclopt/foot_fit/circle_fit_start.hpp"
#include "cyclopt/foot_fit/rolling_foot_fit.hpp"
#include "cyclopt/foot_fit/synthetic_trials.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cf = cyclopt::foot_fit;
namespace foot = cyclopt::foot;

namespace {

// Three trials of one foot: different offsets, directions, speeds of rolling.
std::vector<cf::AnkleTrack> synthetic_tracks(const foot::FootSpec& f, double noise, int trials = 3) {
  std::vector<cf::AnkleTrack> tracks;
  for (int k = 0; k < trials; ++k) {
    cf::SyntheticTrialOptions o;
    o.noise = noise;
    o.offset = 0.4 + 0.11 * k;
    o.walking_direction = 0.02 * (k - 1);
    o.lateral = 0.1 * k;
    o.seed = 17 + k;
    o.foot_angle = cf::default_foot_angle_history(f);
    for (auto& knot : o.foot_angle) knot.t *= 1.0 + 0.07 * k;
    o.source = "trial" + std::to_string(k + 1);
    tracks.push_back(cf::ankle_track(cf::synthetic_trial(f, o)));
  }
  return tracks;
}

double max_relative_length_error(const foot::FootSpec& truth, const cf::FootFitResult& fit) {
  const auto layout = foot::parameter_layout(truth.model);
  double worst = 0.0;
  for (std::size_t i = 0; i < layout.size(); ++i)
    if (layout[i].unit == "m") worst = std::max(worst, std::abs(fit.parameters[i] / truth.parameters[i] - 1.0));
  return worst;
}

}  // namespace

TEST(FootFit, JacobianMatchesCentralDifferences) {
  for (const char* name : {"P1-barefoot-left-HM", "P2-shoes-left-HMT"}) {
    const foot::FootSpec f = foot::foot_preset(name).spec;
    const auto tracks = synthetic_tracks(f, 1e-3, 2);
    const auto residual = cf::rolling_ankle_residual(f.model, tracks);
    const int P = static_cast<int>(f.parameters.size());
    Eigen::VectorXd g(P + 2), l(tracks[0].samples() + tracks[1].samples());
    g.head(P) = f.parameters;
    g.head(P).tail(P - 3).array() += 0.03;  // away from the sharp k = 1e-8 so differences resolve
    g[P] = 0.35;
    g[P + 1] = 0.5;
    for (Eigen::Index j = 0; j < l.size(); ++j) l[j] = -0.3 + 1.2 * double(j) / double(l.size());
    cf::ArrowEvaluation ev, plus, minus;
    ASSERT_TRUE(residual(g, l, true, ev));
    const double h = 1e-6;
    for (int i = 0; i < P + 2; ++i) {
      Eigen::VectorXd gp = g, gm = g;
      gp[i] += h;
      gm[i] -= h;
      ASSERT_TRUE(residual(gp, l, false, plus));
      ASSERT_TRUE(residual(gm, l, false, minus));
      const Eigen::Matrix2Xd fd = (plus.r - minus.r) / (2 * h);
      for (Eigen::Index j = 0; j < l.size(); ++j)
        for (int c = 0; c < 2; ++c)
          EXPECT_NEAR(ev.global_jacobian(2 * j + c, i), fd(c, j), 1e-6 * (1 + std::abs(fd(c, j)))) << name << " global " << i;
    }
    for (Eigen::Index j = 0; j < l.size(); j += 7) {
      Eigen::VectorXd lp = l, lm = l;
      lp[j] += h;
      lm[j] -= h;
      ASSERT_TRUE(residual(g, lp, false, plus));
      ASSERT_TRUE(residual(g, lm, false, minus));
      for (int c = 0; c < 2; ++c)
        EXPECT_NEAR(ev.local_jacobian(c, j), (plus.r(c, j) - minus.r(c, j)) / (2 * h), 1e-7) << name << " local " << j;
    }
  }
}

TEST(FootFit, GroundCircleThroughExactPoints) {
  std::vector<double> x, z;
  for (int j = 0; j < 20; ++j) {
    const double a = 1.0 + 0.02 * j;  // points of a circle about (-0.05, 0), radius 0.1
    x.push_back(-0.05 + 0.1 * std::cos(a));
    z.push_back(0.1 * std::sin(a));
  }
  const cf::GroundCircle c = cf::fit_ground_circle(x, z, true);
  EXPECT_NEAR(c.centre, -0.05, 1e-12);
  EXPECT_NEAR(c.radius, 0.1, 1e-12);
  EXPECT_FALSE(c.centre_on_bound);
  const cf::GroundCircle bounded = cf::fit_ground_circle(x, z, false);  // centre must be >= 0
  EXPECT_TRUE(bounded.centre_on_bound);
  EXPECT_EQ(bounded.centre, 0.0);
}

// Acceptance 2 on the 16 catalogue feet of section 9.2 (HM and HMT, barefoot and shoes) and the
// default preset; the whole catalogue runs in bench/foot_fit_bench.
TEST(FootFit, NoiseFreeTrialsReturnTheGeneratingFoot) {
  int fitted = 0;
  for (const foot::FootPreset& preset : foot::foot_presets()) {
    if (!preset.fitted || !preset.fitted->flag.empty()) continue;
    if (!preset.fitted->section_9_2 && preset.alias != "P2-shoes-left-HMT") continue;
    const auto tracks = synthetic_tracks(preset.spec, 0.0);
    const cf::CircleFitStart start = cf::circle_fit_start(tracks);
    // The seed's box excludes some of its own feet (e.g. l_MT <= z_min, 4.18b); widen it there.
    cf::FootFitOptions options;
    const cf::FitBounds own = cf::widened_to_contain(cf::seed_bounds(preset.spec.model, start.z_min), preset.spec.parameters);
    (preset.spec.model == foot::FootModel::hm ? options.hm_bounds : options.hmt_bounds) = own;
    const cf::RollingFootFit fit = cf::fit_rolling_foot(tracks, options);
    const cf::FootFitResult& same = preset.spec.model == foot::FootModel::hm ? fit.hm : fit.hmt;
    EXPECT_TRUE(same.converged) << preset.name << ": " << same.message;
    EXPECT_LT(max_relative_length_error(preset.spec, same), 1e-6) << preset.name;
    EXPECT_LT(same.rms, 1e-8) << preset.name;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(same.x_off[k], 0.4 + 0.11 * k, 1e-7) << preset.name;
    EXPECT_TRUE(same.convexity.convex) << preset.name;
    EXPECT_LE(fit.hmt.rms, fit.hm.rms * (1 + 1e-9) + 1e-12) << preset.name;
    ++fitted;
  }
  EXPECT_GE(fitted, 16);
}
