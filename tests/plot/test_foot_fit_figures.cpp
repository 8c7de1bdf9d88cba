// The figures of a foot fit on a real recording (issue 56 item 5): per recording the ankle
// height over time with its stances - fitted ones in the colour their track has in the fit
// figures, refused ones dashed with the reason - and the fitted ankle with one colour per trial.
#include "cyclopt/foot_fit/gait_trial_file.hpp"
#include "cyclopt/plot/foot_fit_figures.hpp"
#include "png_inspection.hpp"

#include <gtest/gtest.h>

#include <set>

namespace ff = cyclopt::foot_fit;
namespace plot = cyclopt::plot;

namespace {

const std::string kData = std::string(CYCLOPT_SOURCE_DIR) + "/tests/foot_fit/data/";

std::vector<ff::GaitTrial> both_feet_of_test_walking() {
  std::vector<ff::GaitTrial> trials;
  for (const std::string side : {"L", "R"}) {
    ff::GaitTrialOptions o;
    o.ankle.markers = {side + "LMAL", side + "MMAL"};
    trials.push_back(ff::read_gait_trial(kData + "test_walking_ankles.trc", o));
  }
  return trials;
}

bool same(const plot::Color& a, const plot::Color& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

}  // namespace

TEST(FootFitFigures, StancesOverTimeInTheColoursOfTheirTracks) {
  const std::vector<ff::GaitTrial> trials = both_feet_of_test_walking();  // L: refused, fitted; R: fitted, refused
  const std::vector<plot::Figure> figures = plot::stance_figures(trials);
  ASSERT_EQ(figures.size(), 2u);
  EXPECT_EQ(figures[0].name, "fit_stances_1");
  EXPECT_EQ(figures[1].name, "fit_stances_2");
  const auto& left = std::get<plot::LineChart>(figures[0].drawing);
  const auto& right = std::get<plot::LineChart>(figures[1].drawing);
  ASSERT_EQ(left.series.size(), 3u);  // the ankle, two stances
  EXPECT_TRUE(left.series[1].dashed);
  EXPECT_EQ(left.series[1].label, "stance 1, kinematics: refused, cut by the start of the ankle markers' data");
  EXPECT_FALSE(left.series[2].dashed);
  EXPECT_TRUE(same(*left.series[2].color, plot::palette(0)));  // the first fitted stance: track 0
  EXPECT_TRUE(same(*right.series[1].color, plot::palette(1)));  // the second: track 1
  EXPECT_EQ(right.series[2].label, "stance 2, kinematics: refused, cut by the end of the ankle markers' data");
  // A stance's curve is the ankle height over its frames.
  const ff::Stance& s = trials[1].stances[0];
  ASSERT_EQ(right.series[1].x.size(), static_cast<std::size_t>(s.last - s.first + 1));
  EXPECT_EQ(right.series[1].x.front(), s.start);
  EXPECT_EQ(right.series[1].y.front(), trials[1].ankle.height(s.first));
  // Drawn: both track colours appear in the pictures.
  const auto dir = plot::testing::output_dir("cyclopt_foot_fit_figures");
  plot::write_figure(figures[0], dir.string());
  plot::write_figure(figures[1], dir.string());
  EXPECT_GT(plot::testing::inspect_png((dir / "fit_stances_1.png").string()).count(plot::palette(0)), 200);
  EXPECT_GT(plot::testing::inspect_png((dir / "fit_stances_2.png").string()).count(plot::palette(1)), 200);
  EXPECT_EQ(plot::testing::inspect_png((dir / "fit_stances_1.png").string()).count(plot::palette(1)), 0);
}

TEST(FootFitFigures, OneColourPerTrialInTheFittedAnkle) {
  ff::GaitTrialOptions o;
  o.ankle.markers = {"R.Ankle"};
  o.forces_file = kData + "grf_walk_every10th.mot";
  const std::vector<ff::AnkleTrack> tracks = ff::stance_tracks({ff::read_gait_trial(kData + "motion_capture_walk_ankles.trc", o)});
  ASSERT_EQ(tracks.size(), 2u);  // two stances of the right foot
  const ff::RollingFootFit fit = ff::fit_rolling_foot(tracks);
  const plot::Scene scene = plot::fitted_ankle_scene(tracks, fit.hm);
  std::set<std::string> legends;
  for (const plot::Marker& m : scene.markers) {
    if (m.legend.rfind("measured: ", 0) != 0) continue;
    legends.insert(m.legend);
    const int k = m.legend == "measured: " + tracks[0].source ? 0 : 1;
    EXPECT_TRUE(same(m.color, plot::palette(k))) << m.legend;
  }
  EXPECT_EQ(legends.size(), 2u);
}
