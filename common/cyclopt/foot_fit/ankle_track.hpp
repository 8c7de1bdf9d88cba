#pragma once
// The ankle (SG) trajectory of one trial in the sagittal plane during the rolling phase, the
// data the fits of seed 001 section 4.2 use: x~ along the walking direction, z~ above ground.

#include "cyclopt/foot_fit/marker_trial.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cyclopt::foot_fit {

struct AnkleTrackOptions {
  // One marker (used as the ankle) or two whose mean is the ankle, eq. (4.1).
  std::vector<std::string> markers = {"LMAL", "MMAL"};
  int vertical_axis = 2;        // 0, 1, 2 = file x, y, z (OpenSim files are often y-up)
  double ground_height = 0.0;   // m, ground level along the vertical axis
  // Walking direction as an angle (rad) in the horizontal plane from the first horizontal axis
  // towards the second; when absent it is estimated from the data (eq. 4.2-4.3).
  std::optional<double> walking_direction;
  // Rolling phase, first that applies: an explicit time interval (s); an analog column (the
  // force plate, eq. 4.5: samples from the first to the last with |value| > force_threshold);
  // else the kinematic rule: the longest run of samples, around the lowest ankle position,
  // whose ankle speed stays below max_rolling_speed.
  std::optional<std::pair<double, double>> interval;
  std::string force_column = "Fz";  // used when the trial has this analog column
  double force_threshold = 20.0;    // N
  double max_rolling_speed = 2.0;   // m/s
  int min_samples = 10;             // a rolling phase with fewer samples is an error
};

struct AnkleTrack {
  std::string source;
  std::vector<double> time;  // s
  std::vector<double> x;     // m, along the walking direction (through the lab origin)
  std::vector<double> z;     // m, above the ground
  double walking_direction = 0.0;  // rad, as in AnkleTrackOptions
  bool direction_estimated = false;
  int first_sample = 0;            // rolling phase [first, last] in the trial's samples
  int last_sample = 0;
  std::string phase_rule;          // "interval", "force column Fz", "kinematics"
  int samples() const { return static_cast<int>(x.size()); }
};

// Ankle track of one trial; throws TrialFormatError for a missing marker or force column
// problems (naming file, line, column) and std::invalid_argument for bad options.
AnkleTrack ankle_track(const MarkerTrial& trial, const AnkleTrackOptions& options = {});

// Walking direction (rad) of horizontal points: the principal axis of their scatter, oriented
// along the motion from first to last point. Eq. (4.2)-(4.3) fit y = a x + b by least squares;
// the principal axis is the same line when the walk is along x and stays defined along y.
double walking_direction(const std::vector<Eigen::Vector2d>& horizontal);

}  // namespace cyclopt::foot_fit
