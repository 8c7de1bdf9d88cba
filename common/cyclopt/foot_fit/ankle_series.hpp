#pragma once
// The ankle (SG) of one foot over a whole recording, eq. (4.1): the mean of the malleolus
// markers (or one ankle marker) per frame, with short gaps in those markers filled and the
// vertical axis given or detected. Stances are found in it (stances.hpp) and their sagittal
// tracks taken from it (ankle_track.hpp).

#include "cyclopt/foot_fit/marker_trial.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace cyclopt::foot_fit {

struct AnkleSeriesOptions {
  // One marker (used as the ankle) or two whose mean is the ankle, eq. (4.1).
  std::vector<std::string> markers = {"LMAL", "MMAL"};
  std::optional<int> vertical_axis;  // 0, 1, 2 = file x, y, z; absent: detected (vertical_axis.hpp)
  double ground_height = 0.0;        // m, ground level along the vertical axis
  // Interior gaps of the ankle markers up to this long (s, from the last frame before to the
  // first after) are filled by linear interpolation; at the 200-250 Hz of gait labs 50 ms is
  // 10-12 frames, over which a rolling ankle moves a few millimetres from a straight line.
  double max_gap = 0.05;
  // Walking direction (rad) in the horizontal plane from the first horizontal axis towards the
  // second; absent: the principal axis of the ankle's whole path (eq. 4.2-4.3 over the trial).
  std::optional<double> walking_direction;
};

// Frames [first, last] (0-based samples) in which an ankle marker is missing.
struct AnkleGap {
  int first = 0, last = 0;
  bool filled = false;  // interior and at most max_gap long
};

struct AnkleSeries {
  std::string source;
  std::vector<std::string> markers;
  std::vector<double> time;                // s
  std::vector<int> line_of_sample;         // file line of each frame
  std::vector<Eigen::Vector3d> position;   // m in the file's axes; NaN where missing after filling
  std::vector<AnkleGap> gaps;
  int vertical_axis = 2;
  std::string vertical_rule;               // "given" or "detected: y (evidence)"
  std::vector<std::string> notes;          // e.g. a given vertical axis the data contradict
  double ground_height = 0.0;
  double max_gap = 0.05;
  double walking_direction = 0.0;  // rad, as AnkleSeriesOptions
  bool direction_estimated = false;

  int samples() const { return static_cast<int>(time.size()); }
  bool present(int i) const { return position[i].allFinite(); }
  double height(int i) const { return position[i][vertical_axis] - ground_height; }
  // The file lines of samples [first, last] with their times, for messages: "lines 12-40 at
  // 0.044-0.156 s" or "line 12 at 0.044 s".
  std::string frames(int first, int last) const;
};

// Throws TrialFormatError for a missing marker (at the line naming the markers), when no frame
// has all ankle markers, or when the vertical axis is not given and cannot be detected (the
// message names --vertical-axis and the evidence); std::invalid_argument for bad options.
AnkleSeries ankle_series(const MarkerTrial& trial, const AnkleSeriesOptions& options = {});

// Walking direction (rad) of horizontal points: the principal axis of their scatter, oriented
// along the motion from first to last point. Eq. (4.2)-(4.3) fit y = a x + b by least squares;
// the principal axis is the same line when the walk is along x and stays defined along y.
double walking_direction(const std::vector<Eigen::Vector2d>& horizontal);

}  // namespace cyclopt::foot_fit
