// Marker files (issue 20 item 1, acceptance 4): .trc and CSV written by the synthetic generator
// read back; malformed files rejected naming file, line and column; the ankle track's rolling
// phase (force column, kinematics, interval) and walking direction.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot_fit/ankle_track.hpp"
#include "cyclopt/foot_fit/marker_csv_file.hpp"
#include "cyclopt/foot_fit/synthetic_trials.hpp"
#include "cyclopt/foot_fit/trc_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace cf = cyclopt::foot_fit;
namespace foot = cyclopt::foot;

namespace {

cf::MarkerTrial sample_trial(double swing_time = 0.0) {
  cf::SyntheticTrialOptions o;
  o.noise = 0.0005;
  o.offset = 1.2;
  o.walking_direction = 0.3;
  o.swing_time = swing_time;
  o.source = "walk1";
  return cf::synthetic_trial(foot::foot_preset("P1-barefoot-left-HM").spec, o);
}

std::string trc_text(const cf::MarkerTrial& t) {
  std::ostringstream out;
  cf::write_trc(t, out, "mm");
  return out.str();
}

std::string csv_text(const cf::MarkerTrial& t) {
  std::ostringstream out;
  cf::write_marker_csv(t, out, "mm");
  return out.str();
}

// Replaces field `column` (1-based) of line `line` (1-based) of `text`.
std::string with_field(const std::string& text, int line, int column, const std::string& value, char delimiter) {
  std::istringstream in(text);
  std::ostringstream out;
  std::string l;
  for (int n = 1; std::getline(in, l); ++n) {
    if (n == line) {
      std::vector<std::string> f;
      std::stringstream ls(l);
      std::string field;
      while (std::getline(ls, field, delimiter)) f.push_back(field);
      f.at(column - 1) = value;
      l.clear();
      for (std::size_t i = 0; i < f.size(); ++i) l += (i ? std::string(1, delimiter) : "") + f[i];
    }
    out << l << "\n";
  }
  return out.str();
}

template <class Read>
void expect_error_at(Read read, const std::string& text, int line, int column, const std::string& words) {
  try {
    read(text);
    ADD_FAILURE() << "accepted a malformed file (expected " << words << ")";
  } catch (const cf::TrialFormatError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.column(), column) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("bad.file:" + std::to_string(line) + ":" + std::to_string(column) + ":", 0), 0u) << e.what();
  }
}

cf::MarkerTrial read_trc_text(const std::string& s) {
  std::istringstream in(s);
  return cf::read_trc(in, "bad.file");
}
cf::MarkerTrial read_csv_text(const std::string& s) {
  std::istringstream in(s);
  return cf::read_marker_csv(in, "bad.file");
}

}  // namespace

TEST(MarkerFiles, TrcAndCsvRoundTrip) {
  const cf::MarkerTrial t = sample_trial();
  for (int format = 0; format < 2; ++format) {
    const cf::MarkerTrial back = format == 0 ? read_trc_text(trc_text(t)) : read_csv_text(csv_text(t));
    ASSERT_EQ(back.samples(), t.samples());
    ASSERT_EQ(back.marker_names, t.marker_names);
    for (std::size_t m = 0; m < t.positions.size(); ++m)
      for (int i = 0; i < t.samples(); ++i) EXPECT_LT((back.positions[m][i] - t.positions[m][i]).norm(), 1e-10);
    EXPECT_EQ(back.analog_names.size(), format == 0 ? 0u : 1u);  // .trc has no analog channels
  }
}

TEST(MarkerFiles, MalformedTrcRejectedWithLineAndColumn) {
  const std::string good = trc_text(sample_trial());
  // Data rows start at line 7 (five header lines and a blank one); LMAL X is column 3.
  expect_error_at(read_trc_text, with_field(good, 9, 4, "inf", '\t'), 9, 4, "not finite");
  expect_error_at(read_trc_text, with_field(good, 9, 2, "", '\t'), 9, 2, "empty field");
  expect_error_at(read_trc_text, with_field(good, 9, 2, "nan", '\t'), 9, 2, "not finite");
  expect_error_at(read_trc_text, with_field(good, 12, 2, "0.001", '\t'), 12, 2, "does not increase");
  expect_error_at(read_trc_text, with_field(good, 3, 5, "furlong", '\t'), 3, 5, "not one of mm, cm, m");
  expect_error_at(read_trc_text, with_field(good, 3, 5, "m", '\t'), 7, 3, "the stated unit 'm' is wrong");
  expect_error_at(read_trc_text, with_field(good, 10, 6, "12x", '\t'), 10, 6, "not a number");
  // A missing marker is reported at the line naming the markers.
  const cf::MarkerTrial t = read_trc_text(good);
  cf::AnkleTrackOptions o;
  o.markers = {"LMAL", "RMAL"};
  try {
    cf::ankle_track(t, o);
    ADD_FAILURE() << "missing marker accepted";
  } catch (const cf::TrialFormatError& e) {
    EXPECT_EQ(e.line(), 4);
    EXPECT_NE(std::string(e.what()).find("no marker named 'RMAL'"), std::string::npos) << e.what();
  }
}

TEST(MarkerFiles, MalformedCsvRejectedWithLineAndColumn) {
  const std::string good = csv_text(sample_trial());
  // Line 1 "# units", 2 "# source", 3 header, data from line 4; columns: time, LMAL_x..., Fz (8).
  expect_error_at(read_csv_text, with_field(good, 6, 1, "NaN", ','), 6, 1, "not finite");
  expect_error_at(read_csv_text, with_field(good, 6, 8, "NaN", ','), 6, 8, "Fz: 'NaN' is not finite");
  expect_error_at(read_csv_text, with_field(good, 6, 3, "-1e999", ','), 6, 3, "not a number");
  expect_error_at(read_csv_text, with_field(good, 8, 1, "0", ','), 8, 1, "does not increase");
  expect_error_at(read_csv_text, with_field(good, 3, 4, "LMAL_q", ','), 3, 0, "has no column LMAL_z");
  std::string metres = good;
  metres.replace(metres.find("# units: mm"), 11, "# units: m");
  expect_error_at(read_csv_text, metres, 4, 2, "the stated unit 'm' is wrong");
  std::string no_units = good.substr(good.find('\n') + 1);
  expect_error_at(read_csv_text, no_units, 1, 0, "units not stated");
}

// Occluded markers: a blank or NaN coordinate, or a marker at exactly (0, 0, 0), is a missing
// sample, not a malformed file (issue 56: one NaN in any marker used to reject the trial).
TEST(MarkerFiles, MissingSamplesAreReadAsNaN) {
  const std::string good = trc_text(sample_trial());
  // Line 9 is sample 2: LMAL X (column 3) NaN, MMAL (columns 6-8) all zero, line 10 LMAL Y blank.
  std::string text = with_field(good, 9, 3, "NaN", '\t');
  for (int c = 6; c <= 8; ++c) text = with_field(text, 9, c, "0.000", '\t');
  text = with_field(text, 10, 4, "", '\t');
  const cf::MarkerTrial t = read_trc_text(text);
  EXPECT_FALSE(t.present(0, 2));
  EXPECT_FALSE(t.present(1, 2));
  EXPECT_FALSE(t.present(0, 3));
  EXPECT_TRUE(t.present(1, 3));
  EXPECT_TRUE(std::isnan(t.positions[0][2].y())) << "a sample is missing as a whole";
  // A single zero coordinate is a coordinate, not a gap.
  const cf::MarkerTrial one_zero = read_trc_text(with_field(good, 9, 5, "0", '\t'));
  EXPECT_TRUE(one_zero.present(0, 2));
  EXPECT_EQ(one_zero.positions[0][2].z(), 0.0);
  // The same in CSV (line 4 is sample 0; LMAL_x is column 2).
  const cf::MarkerTrial csv = read_csv_text(with_field(csv_text(sample_trial()), 5, 2, "", ','));
  EXPECT_FALSE(csv.present(0, 1));
  EXPECT_TRUE(csv.present(1, 1));
}

// A header padded with runs of tabs (OpenSim's motion_capture_walk.trc), and rows that stop
// early where the last markers are missing.
TEST(MarkerFiles, TrcHeaderPaddedWithTabsAndShortRows) {
  const std::string text =
      "PathFileType  4\t(X/Y/Z) C:\\walk.trc\n"
      "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n"
      "  100.0\t\t  100.0\t\t      3\t\t      2\t\t mm\t  100.0\t      1\t      3\n"
      "Frame#\tTime\tR.Ankle\t\t\tL.Ankle\t\t\t\n"
      "\t\tX1\tY1\tZ1\tX2\tY2\tZ2\t\n"
      "\n"
      "1\t0.00\t-838.277\t272.831\t-132.182\t-608.572\t108.068\t-342.461\n"
      "2\t0.01\t-807.973\t266.653\t-130.959\n"
      "3\t0.02\t-777.5\t260.0\t-130.0\t-608.3\t108.3\t-342.5\t\t\n";
  const cf::MarkerTrial t = read_trc_text(text);
  EXPECT_EQ(t.units, "mm");
  ASSERT_EQ(t.marker_names, (std::vector<std::string>{"R.Ankle", "L.Ankle"}));
  ASSERT_EQ(t.samples(), 3);
  EXPECT_NEAR(t.positions[0][1].x(), -0.807973, 1e-12);
  EXPECT_FALSE(t.present(1, 1));
  EXPECT_TRUE(t.present(1, 2));
  expect_error_at(read_trc_text, text.substr(0, text.size() - 1) + "\t7\n", 9, 11, "the header names 2 markers");
}

TEST(AnkleTrack, RollingPhaseFromForceKinematicsAndInterval) {
  const double swing = 0.1;
  const cf::MarkerTrial t = sample_trial(swing);
  const int strike = static_cast<int>(std::lround(swing * 200.0));
  const int toe_off = strike + static_cast<int>(std::lround(0.62 * 200.0));
  const cf::AnkleTrack by_force = cf::ankle_track(t);
  EXPECT_EQ(by_force.phase_rule, "force column Fz");
  EXPECT_EQ(by_force.first_sample, strike);
  EXPECT_EQ(by_force.last_sample, toe_off);
  cf::AnkleTrackOptions kin;
  kin.force_column = "none";
  const cf::AnkleTrack by_kinematics = cf::ankle_track(t, kin);
  EXPECT_EQ(by_kinematics.phase_rule, "kinematics");
  EXPECT_LE(std::abs(by_kinematics.first_sample - strike), 1);
  EXPECT_LE(std::abs(by_kinematics.last_sample - toe_off), 1);
  cf::AnkleTrackOptions given;
  given.interval = {{0.2, 0.4}};
  const cf::AnkleTrack by_interval = cf::ankle_track(t, given);
  EXPECT_EQ(by_interval.first_sample, 40);
  EXPECT_EQ(by_interval.last_sample, 80);
}

TEST(AnkleTrack, WalkingDirectionAndSagittalCoordinates) {
  cf::SyntheticTrialOptions o;
  o.offset = 0.8;
  o.walking_direction = -0.4;
  o.lateral = 0.25;
  const foot::FootSpec f = foot::foot_preset("P1-shoes-left-HMT").spec;
  const cf::AnkleTrack track = cf::ankle_track(cf::synthetic_trial(f, o));
  EXPECT_NEAR(track.walking_direction, -0.4, 1e-9);
  EXPECT_TRUE(track.direction_estimated);
  // The flat-foot sample (theta = 0 at t = 0.12 s) sits at the offset and at height F'(0).
  const Eigen::Vector2d flat = cf::synthetic_ankle(f, 0.0, 0.8);
  const int j = static_cast<int>(std::lround(0.12 * 200.0));
  EXPECT_NEAR(track.x[j], flat.x(), 1e-9);
  EXPECT_NEAR(track.z[j], flat.y(), 1e-9);
  EXPECT_NEAR(flat.x(), 0.8, 1e-15);
}
