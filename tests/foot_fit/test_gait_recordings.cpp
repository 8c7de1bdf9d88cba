// Real gait-lab recordings (issue 56), on the excerpts of OpenSim's test_walking.trc and of the
// Rajagopal walk (motion_capture_walk.trc with grf_walk.mot) in tests/foot_fit/data (README
// there: source, licence, what was kept): the files read as published, the vertical axis and the
// stances are found, a stance the recording cuts is refused and never fitted, every foot fits
// without a hand-given interval with its HMT parameters in the range of the seed's own fits
// (appendix B), and the spreads over strides and boundaries are reported.
#include "cyclopt/foot_fit/ankle_track.hpp"
#include "cyclopt/foot_fit/boundary_grid.hpp"
#include "cyclopt/foot_fit/fit_spread.hpp"
#include "cyclopt/foot_fit/gait_trial_file.hpp"
#include "cyclopt/foot_fit/marker_file.hpp"
#include "cyclopt/foot_fit/opensim_storage_file.hpp"
#include "cyclopt/foot_fit/rolling_foot_fit.hpp"
#include "cyclopt/foot_fit/seed_fitted_ranges.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <sstream>
#include <thread>
#include <utility>

namespace cf = cyclopt::foot_fit;
namespace foot = cyclopt::foot;

namespace {

const std::string kData = std::string(CYCLOPT_SOURCE_DIR) + "/tests/foot_fit/data/";
const std::string kTestWalking = kData + "test_walking_ankles.trc";
const std::string kWalk = kData + "motion_capture_walk_ankles.trc";
const std::string kForces = kData + "grf_walk_every10th.mot";

cf::GaitTrial test_walking(const std::string& side) {
  cf::GaitTrialOptions o;
  o.ankle.markers = {side + "LMAL", side + "MMAL"};
  return cf::read_gait_trial(kTestWalking, o);
}

cf::GaitTrial rajagopal_walk(const std::string& side) {
  cf::GaitTrialOptions o;
  o.ankle.markers = {side + ".Ankle"};
  o.forces_file = kForces;
  return cf::read_gait_trial(kWalk, o);
}

// The HMT shape parameters inside the range the seed's fits span (Tables B.6-B.11).
void expect_in_seed_range(const cf::FootFitResult& f, const std::string& what) {
  for (int i : {foot::hmt::h_F, foot::hmt::l_HA, foot::hmt::l_HM, foot::hmt::l_MT, foot::hmt::gamma_F}) {
    const cf::SeedRange r = cf::seed_fitted_range(foot::FootModel::hmt, i);
    EXPECT_GE(f.parameters[i], r.low) << what << " " << f.estimates[i].name;
    EXPECT_LE(f.parameters[i], r.high) << what << " " << f.estimates[i].name;
  }
}

}  // namespace

TEST(GaitRecordings, FilesReadAsPublished) {
  const cf::MarkerTrial tw = cf::read_marker_file(kTestWalking);
  EXPECT_EQ(tw.samples(), 556);
  EXPECT_EQ(tw.units, "mm");
  // The malleoli are stored as 0.0 outside 1.168-2.848 s: missing, not at the lab origin.
  const int rlmal = tw.marker_index("RLMAL");
  EXPECT_FALSE(tw.present(rlmal, 0));
  EXPECT_TRUE(tw.present(rlmal, 200));
  EXPECT_FALSE(tw.present(rlmal, tw.samples() - 1));
  // The header's fields are separated by pairs of tabs (the reader once took NumFrames for the unit).
  const cf::MarkerTrial walk = cf::read_marker_file(kWalk);
  EXPECT_EQ(walk.units, "mm");
  EXPECT_EQ(walk.samples(), 238);
  EXPECT_EQ(walk.marker_names, (std::vector<std::string>{"R.Shoulder", "R.Ankle", "L.Ankle"}));
  const cf::StorageTable grf = cf::read_opensim_storage(kForces);
  EXPECT_EQ(grf.rows(), 478);
  EXPECT_EQ(grf.names.size(), 12u);
  const std::vector<cf::ForceChannel> plates = cf::ground_reaction_channels(grf, 1);
  ASSERT_EQ(plates.size(), 2u);
  EXPECT_EQ(plates[0].name, "ground_force_r_");
  EXPECT_EQ(plates[1].name, "ground_force_l_");
  EXPECT_EQ(plates[0].cop.size(), 478u);
  EXPECT_GT(plates[0].vertical_at(0.6), 500.0);  // N: the right foot in mid stance
}

TEST(GaitRecordings, StorageFileErrorsNameLineAndColumn) {
  auto error_of = [](const std::string& text) {
    std::istringstream in(text);
    try {
      cf::read_opensim_storage(in, "grf.mot");
    } catch (const cf::TrialFormatError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string head = "grf\nversion=1\nnRows=2\nnColumns=3\ninDegrees=no\nendheader\ntime\tf_vy\tf_py\n";
  EXPECT_EQ(error_of(head + "0.0\t1\t2\n0.1\t3\t4\n"), "accepted");
  EXPECT_EQ(error_of(head + "0.0\t1\t2\n0.1\t3\n"), "grf.mot:9:3: row has 2 fields, line 7 names 3 columns");
  EXPECT_EQ(error_of(head + "0.0\t1\t2\n0.1\tabc\t4\n"), "grf.mot:9:2: f_vy: 'abc' is not a number");
  EXPECT_EQ(error_of(head + "0.1\t1\t2\n0.1\t3\t4\n"), "grf.mot:9:1: time 0.100000 s does not increase (previous row 0.100000 s)");
  EXPECT_EQ(error_of("grf\nnColumns=4\nendheader\ntime\tf_vy\tf_py\n"), "grf.mot:2:1: nColumns says 4 but line 4 names 3");
  EXPECT_EQ(error_of("time\tf_vy\n0\t1\n"), "grf.mot:2:0: no line 'endheader': not an OpenSim storage file (.mot, .sto)");
}

TEST(GaitRecordings, VerticalAxisFoundOrAskedFor) {
  EXPECT_EQ(test_walking("R").ankle.vertical_axis, 2);
  EXPECT_EQ(rajagopal_walk("R").ankle.vertical_axis, 1);
  // Told the wrong axis, the fit follows but says so.
  cf::GaitTrialOptions told;
  told.ankle.markers = {"R.Ankle"};
  told.ankle.vertical_axis = 2;
  const cf::GaitTrial wrong = cf::read_gait_trial(kWalk, told);
  ASSERT_EQ(wrong.ankle.notes.size(), 1u);
  EXPECT_NE(wrong.ankle.notes[0].find("suggest that y points up"), std::string::npos) << wrong.ankle.notes[0];
  // One marker that rises as much as it sways, nothing else: no guess, a message naming the option.
  cf::MarkerTrial t;
  t.source = "square.trc";
  t.marker_names = {"ANK"};
  t.positions.resize(1);
  for (int i = 0; i < 50; ++i) {
    t.time.push_back(0.01 * i);
    t.line_of_sample.push_back(7 + i);
    t.positions[0].emplace_back(0.02 * i, 0.1 + 0.05 * std::sin(0.3 * i), 0.1 + 0.05 * std::cos(0.3 * i));
  }
  cf::AnkleSeriesOptions o;
  o.markers = {"ANK"};
  try {
    cf::ankle_series(t, o);
    ADD_FAILURE() << "guessed a vertical axis";
  } catch (const cf::TrialFormatError& e) {
    EXPECT_NE(std::string(e.what()).find("--vertical-axis"), std::string::npos) << e.what();
  }
}

// Acceptance 2: the right foot's second stance in test_walking runs into the end of the malleoli's
// data (2.848 s) and the left foot's first one starts with it; both are refused, never fitted.
TEST(GaitRecordings, StancesCutByTheRecordingAreRefused) {
  const cf::GaitTrial right = test_walking("R"), left = test_walking("L");
  ASSERT_EQ(right.stances.size(), 2u);
  EXPECT_TRUE(right.stances[0].complete());
  EXPECT_NEAR(right.stances[0].start, 1.62, 0.03);
  EXPECT_NEAR(right.stances[0].end, 2.22, 0.03);
  EXPECT_EQ(right.stances[1].refusal.rfind("cut by the end of the ankle markers' data", 0), 0u) << right.stances[1].refusal;
  ASSERT_EQ(left.stances.size(), 2u);
  EXPECT_EQ(left.stances[0].refusal.rfind("cut by the start of the ankle markers' data", 0), 0u) << left.stances[0].refusal;
  EXPECT_TRUE(left.stances[1].complete());
  const std::vector<cf::AnkleTrack> tracks = cf::stance_tracks({right});
  ASSERT_EQ(tracks.size(), 1u);
  EXPECT_LT(tracks[0].time.back(), 2.3);
  EXPECT_THROW(cf::stance_track(right, 1), std::invalid_argument);
  // Cut by the force recording: the right plate's first loaded run, with the file started at 0.5 s.
  const cf::GaitTrial walk = rajagopal_walk("R");
  cf::StorageTable late = cf::read_opensim_storage(kForces);
  int from = 0;
  while (late.time[from] < 0.5) ++from;
  late.time.erase(late.time.begin(), late.time.begin() + from);
  for (auto& c : late.columns) c.erase(c.begin(), c.begin() + from);
  const std::vector<cf::Stance> s = cf::force_stances(walk.ankle, cf::ground_reaction_channels(late, 1), true);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].refusal.rfind("cut by the start of the force recording", 0), 0u) << s[0].refusal;
  EXPECT_TRUE(s[1].complete());
}

// Plates go to the foot whose ankle is near their centre of pressure; the kinematic rule finds
// the same stances 20-60 ms early (StanceOptions).
TEST(GaitRecordings, ForcePlatesAssignedByCentreOfPressure) {
  const cf::GaitTrial right = rajagopal_walk("R"), left = rajagopal_walk("L");
  ASSERT_EQ(right.stances.size(), 2u);
  ASSERT_EQ(left.stances.size(), 1u);
  EXPECT_EQ(right.stances[0].rule, "force ground_force_r_");
  EXPECT_EQ(left.stances[0].rule, "force ground_force_l_");
  EXPECT_NEAR(right.stances[0].start, 0.27, 0.006);  // grf_walk.mot: above 20 N from 0.2680 s to 1.0225 s
  EXPECT_NEAR(right.stances[0].end, 1.02, 0.006);
  EXPECT_NEAR(right.stances[1].start, 1.42, 0.006);
  EXPECT_NEAR(left.stances[0].start, 0.84, 0.006);
  for (const cf::Stance& s : right.stances) EXPECT_TRUE(s.complete()) << s.refusal;
  const std::vector<cf::Stance> kinematic = cf::kinematic_stances(right.ankle);
  ASSERT_EQ(kinematic.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    EXPECT_LE(right.stances[k].start - kinematic[k].start, 0.06) << k;
    EXPECT_GE(right.stances[k].start - kinematic[k].start, 0.0) << k;
    EXPECT_LE(right.stances[k].end - kinematic[k].end, 0.07) << k;
    EXPECT_GE(right.stances[k].end - kinematic[k].end, 0.0) << k;
  }
}

// A short gap of the ankle marker is filled; a long one excludes the stance, naming the lines.
TEST(GaitRecordings, GapsInTheAnkleMarkers) {
  cf::MarkerTrial t = cf::read_marker_file(kWalk);
  const int ankle = t.marker_index("R.Ankle");
  cf::AnkleSeriesOptions o;
  o.markers = {"R.Ankle"};
  const cf::AnkleSeries whole = cf::ankle_series(t, o);
  for (int i = 50; i < 54; ++i) t.positions[ankle][i].setConstant(std::nan(""));  // 40 ms at 100 Hz
  cf::AnkleSeries filled = cf::ankle_series(t, o);
  ASSERT_EQ(filled.gaps.size(), 1u);
  EXPECT_TRUE(filled.gaps[0].filled);
  for (int i = 50; i < 54; ++i) EXPECT_LT((filled.position[i] - whole.position[i]).norm(), 2e-3) << i;
  for (int i = 54; i < 60; ++i) t.positions[ankle][i].setConstant(std::nan(""));  // now 100 ms
  const cf::AnkleSeries gap = cf::ankle_series(t, o);
  EXPECT_FALSE(gap.gaps[0].filled);
  const std::vector<cf::Stance> s =
      cf::force_stances(gap, cf::ground_reaction_channels(cf::read_opensim_storage(kForces), 1), true);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].refusal, "ankle markers missing (lines 57-66 at 0.500-0.590 s, longer than the 50 ms a gap may be filled)");
  EXPECT_TRUE(s[1].complete());
}

// Acceptance 1: every foot of both recordings fits without a hand-given interval; both fits
// converge and the HMT parameters lie in the range of the seed's own fits.
TEST(GaitRecordings, EveryFootFitsWithinTheSeedsRanges) {
  for (const auto& [name, trial] : {std::pair{"test_walking right", test_walking("R")}, {"test_walking left", test_walking("L")},
                                    {"motion_capture_walk right", rajagopal_walk("R")},
                                    {"motion_capture_walk left", rajagopal_walk("L")}}) {
    const std::vector<cf::AnkleTrack> tracks = cf::stance_tracks({trial});
    ASSERT_FALSE(tracks.empty()) << name;
    const cf::RollingFootFit fit = cf::fit_rolling_foot(tracks);
    EXPECT_TRUE(fit.hm.converged) << name << ": " << fit.hm.message;
    EXPECT_TRUE(fit.hmt.converged) << name << ": " << fit.hmt.message;
    EXPECT_LE(fit.hmt.rms, fit.hm.rms) << name;
    EXPECT_LT(fit.hmt.rms, 2.5e-3) << name;  // m: marker noise and soft tissue, not a wrong phase
    EXPECT_TRUE(fit.hmt.convexity.convex) << name;
    expect_in_seed_range(fit.hmt, name);
  }
}

// The statistical stop (ArrowOptions::parameter_tolerance) ends where the decrease tests end,
// within a tenth of a standard error (test_walking's right foot).
TEST(GaitRecordings, TheStatisticalStopEndsWhereTheDecreaseTestsEnd) {
  const std::vector<cf::AnkleTrack> tracks = cf::stance_tracks({test_walking("R")});
  cf::FootFitOptions statistical, strict;
  statistical.solver.parameter_tolerance = 1e-2;
  strict.solver.max_iterations = 5000;
  const cf::RollingFootFit a = cf::fit_rolling_foot(tracks, statistical), b = cf::fit_rolling_foot(tracks, strict);
  ASSERT_TRUE(a.hmt.converged) << a.hmt.message;
  ASSERT_TRUE(b.hmt.converged) << b.hmt.message;
  for (std::size_t i = 0; i < b.hmt.estimates.size(); ++i) {
    const cf::ParameterEstimate& e = b.hmt.estimates[i];
    if (e.fixed || e.at_bound) continue;
    EXPECT_LT(std::abs(a.hmt.parameters[static_cast<Eigen::Index>(i)] - e.value), 0.1 * e.standard_error) << e.name;
  }
}

// Item 3: with two strides both spreads are reported, and they are what the refits say they
// are - the boundary spread the largest change over the boundary refits (a plate's stance only
// shrinks: start later, end earlier), the stride spread the jackknife of the two single-stride
// fits. The same refits on one thread give the same spreads.
TEST(GaitRecordings, SpreadsOverStridesAndBoundaries) {
  const std::vector<cf::GaitTrial> trials{rajagopal_walk("R")};
  cf::RollingFootFit fit = cf::fit_rolling_foot(cf::stance_tracks(trials));
  const cf::FitSpread spread = cf::add_fit_spread(fit, trials);
  ASSERT_EQ(spread.refits.size(), 2u + 24u);  // leave one out; the 5 x 5 inward shifts but (0, 0)
  EXPECT_EQ(spread.refits[2].what, "start +0 ms, end -10 ms");
  EXPECT_EQ(spread.refits[25].what, "start +40 ms, end -40 ms");
  EXPECT_EQ(fit.hmt.spread_refits, 26);
  EXPECT_EQ(fit.hmt.boundary_tolerance, 0.04);
  for (const cf::FootFitResult* f : {&fit.hm, &fit.hmt})
    for (std::size_t i = 0; i < f->estimates.size(); ++i) {
      const cf::ParameterEstimate& e = f->estimates[i];
      if (e.fixed) {
        EXPECT_TRUE(std::isnan(e.boundary_spread));
        continue;
      }
      const auto refit_value = [&](const cf::Refit& r) { return (f == &fit.hm ? r.hm : r.hmt)[static_cast<Eigen::Index>(i)]; };
      double largest = 0.0;
      for (std::size_t k = 2; k < spread.refits.size(); ++k) largest = std::max(largest, std::abs(refit_value(spread.refits[k]) - e.value));
      EXPECT_EQ(e.boundary_spread, largest) << e.name;
      EXPECT_NEAR(e.stride_spread, 0.5 * std::abs(refit_value(spread.refits[0]) - refit_value(spread.refits[1])),
                  1e-12 * std::abs(e.value) + 1e-15)
          << e.name;
      if (e.at_bound) {
        EXPECT_NE(e.flag.find("on its bound"), std::string::npos) << e.name;
      }
      const double width = cf::seed_fitted_range(f->model, static_cast<int>(i)).width();
      EXPECT_EQ(e.flag.find("boundary spread") != std::string::npos, e.boundary_spread > 0.25 * width) << e.name << ": " << e.flag;
    }
  cf::RollingFootFit serial = cf::fit_rolling_foot(cf::stance_tracks(trials));
  cf::SpreadOptions one_thread;
  one_thread.threads = 1;
  cf::add_fit_spread(serial, trials, {}, one_thread);
  for (std::size_t i = 0; i < fit.hmt.estimates.size(); ++i) {
    const cf::ParameterEstimate &a = fit.hmt.estimates[i], &b = serial.hmt.estimates[i];
    EXPECT_TRUE(a.boundary_spread == b.boundary_spread || (std::isnan(a.boundary_spread) && std::isnan(b.boundary_spread))) << a.name;
  }
  // The conditional standard errors understate what a 40 ms boundary does (issue 56).
  EXPECT_GT(fit.hmt.estimates[foot::hmt::l_HA].boundary_spread, 3.0 * fit.hmt.estimates[foot::hmt::l_HA].standard_error);
  // One stride found by the kinematic rule: no stride spread, boundaries moved both ways.
  const std::vector<cf::GaitTrial> one{test_walking("L")};
  cf::RollingFootFit single = cf::fit_rolling_foot(cf::stance_tracks(one));
  cf::SpreadOptions corners;
  corners.boundary_steps = 1;
  // Progress on the calling thread only, counting up to the refits' number, which the last call gives.
  std::vector<std::pair<std::size_t, std::size_t>> progress;
  const std::thread::id caller = std::this_thread::get_id();
  bool elsewhere = false;
  const auto note = [&](std::size_t done, std::size_t total) {
    elsewhere = elsewhere || std::this_thread::get_id() != caller;
    progress.emplace_back(done, total);
  };
  EXPECT_EQ(cf::add_fit_spread(single, one, {}, corners, note).refits.size(), 8u);  // the 3 x 3 shifts but (0, 0)
  EXPECT_FALSE(elsewhere);
  ASSERT_FALSE(progress.empty());
  EXPECT_EQ(progress.back(), std::make_pair(std::size_t{8}, std::size_t{8}));
  for (std::size_t k = 0; k < progress.size(); ++k) {
    EXPECT_EQ(progress[k].second, 8u);
    if (k > 0) {
      EXPECT_GE(progress[k].first, progress[k - 1].first);
    }
  }
  EXPECT_TRUE(std::isnan(single.hmt.estimates[foot::hmt::l_HM].stride_spread));
  EXPECT_FALSE(std::isnan(single.hmt.estimates[foot::hmt::l_HM].boundary_spread));
}

// Acceptance 3 by construction (boundary_grid.hpp): the every-frame grid's data sets hold the
// stance windows of every start and end shift within the tolerance - a 1 ms grid, random shifts,
// the coarser grids - so a check on any finer grid lands on windows the spread refitted; and it
// moves no boundary further than the tolerance. Kinematic stances at 250 Hz, plate stances at
// 100 Hz (only shrinking), and both together (frames on two different grids).
TEST(GaitRecordings, TheBoundaryGridHoldsEveryWindowOfShiftsWithinTheTolerance) {
  const double d = cf::SpreadOptions{}.boundary_tolerance;
  std::mt19937 random(56);
  std::uniform_real_distribution<double> shift(-d, d);
  for (const auto& [name, trials] :
       {std::pair{"test_walking right", std::vector{test_walking("R")}}, {"test_walking left", std::vector{test_walking("L")}},
        {"motion_capture_walk right", std::vector{rajagopal_walk("R")}}, {"motion_capture_walk left", std::vector{rajagopal_walk("L")}},
        {"test_walking right and motion_capture_walk right", std::vector{test_walking("R"), rajagopal_walk("R")}}}) {
    std::set<cf::StanceWindows> grid{cf::stance_windows(cf::stance_tracks(trials))};
    for (const cf::MovedBoundaries& m : cf::boundary_grid(trials, d, 0)) {
      EXPECT_LE(std::abs(m.start_shift), d) << name;
      EXPECT_LE(std::abs(m.end_shift), d) << name;
      EXPECT_TRUE(grid.insert(cf::stance_windows(m.tracks)).second) << name << ": a data set refitted twice";
    }
    std::vector<std::pair<double, double>> shifts;
    for (int i = -40; i <= 40; ++i)
      for (int j = -40; j <= 40; ++j) shifts.emplace_back(1e-3 * i, 1e-3 * j);
    for (int k = 0; k < 2000; ++k) shifts.emplace_back(shift(random), shift(random));
    for (int steps : {1, 3, 4, 7})
      for (const cf::MovedBoundaries& m : cf::boundary_grid(trials, d, steps)) shifts.emplace_back(m.start_shift, m.end_shift);
    for (const auto& [start, end] : shifts)
      EXPECT_TRUE(grid.count(cf::stance_windows(cf::stance_tracks(trials, start, end))))
          << name << ": start " << start << " s, end " << end << " s gives windows the spread did not refit";
  }
}
