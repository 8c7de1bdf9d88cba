#pragma once
// The ankle (SG) trajectory of one stance in the sagittal plane, the data the fits of seed 001
// section 4.2 use: x~ along the walking direction, z~ above ground.

#include "cyclopt/foot_fit/ankle_series.hpp"
#include "cyclopt/foot_fit/marker_trial.hpp"
#include "cyclopt/foot_fit/stances.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cyclopt::foot_fit {

struct AnkleTrack {
  std::string source;
  std::vector<double> time;  // s
  std::vector<double> x;     // m, along the walking direction (through the lab origin)
  std::vector<double> z;     // m, above the ground
  double walking_direction = 0.0;  // rad in the horizontal plane, from the first horizontal axis towards the second
  bool direction_estimated = false;
  int first_sample = 0;            // rolling phase [first, last] in the trial's samples
  int last_sample = 0;
  std::string phase_rule;          // "interval", "force column Fz", "kinematics", ...
  int samples() const { return static_cast<int>(x.size()); }
};

// The sagittal track of frames [first, last] of `ankle` (all present), named `source`; the
// walking direction is given or, when absent, estimated from these frames (eq. 4.2-4.3).
AnkleTrack sagittal_track(const AnkleSeries& ankle, int first, int last, const std::string& source,
                          std::optional<double> walking_direction = std::nullopt);

// A complete stance's track along the trial's walking direction, named "FILE stance K (T0-T1 s)"
// with K its 1-based place among the trial's stances. The shifts (s) move its start and end; a
// moved boundary stops at the last frame before missing ankle data.
AnkleTrack stance_track(const GaitTrial& trial, int stance, double start_shift = 0.0, double end_shift = 0.0);

// The tracks of every complete stance of the trials, in order (what the fit fits), with every start
// moved by start_shift and every end by end_shift (s), except that a stance bounded by a loaded
// plate only shrinks (start later, end earlier): its rolling phase lies within the contact the
// plate measured.
std::vector<AnkleTrack> stance_tracks(const std::vector<GaitTrial>& trials, double start_shift = 0.0, double end_shift = 0.0);

// A trial cut to one rolling phase, as the seed's are (eq. 4.5: the trial starts at first
// contact): synthetic trials and hand-cut recordings. Raw recordings of several steps go through
// stances.hpp instead, which refuses stances the recording cuts.
struct AnkleTrackOptions {
  std::vector<std::string> markers = {"LMAL", "MMAL"};  // as AnkleSeriesOptions
  int vertical_axis = 2;        // 0, 1, 2 = file x, y, z
  double ground_height = 0.0;   // m
  std::optional<double> walking_direction;
  // Rolling phase, first that applies: an explicit time interval (s); an analog column (the
  // force plate, eq. 4.5: samples from the first to the last with |value| > force_threshold);
  // else the kinematic rule: the longest run of samples, around the lowest ankle position,
  // whose ankle speed stays below max_rolling_speed.
  std::optional<std::pair<double, double>> interval;
  std::string force_column = "Fz";
  double force_threshold = 20.0;    // N
  double max_rolling_speed = 2.0;   // m/s
  int min_samples = 10;             // a rolling phase with fewer samples is an error
};

// Throws TrialFormatError for a missing marker or force column problems (naming file, line,
// column) or missing ankle frames in the phase, std::invalid_argument for bad options.
AnkleTrack ankle_track(const MarkerTrial& trial, const AnkleTrackOptions& options = {});

}  // namespace cyclopt::foot_fit
