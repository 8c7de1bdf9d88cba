#include "cyclopt/foot_fit/ankle_track.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace cyclopt::foot_fit {
namespace {

std::pair<int, int> horizontal_axes(int vertical) { return {vertical == 0 ? 1 : 0, vertical == 2 ? 1 : 2}; }

std::pair<int, int> phase_from_force(const MarkerTrial& t, int column, double threshold) {
  int first = -1, last = -1;
  for (int i = 0; i < t.samples(); ++i)
    if (std::abs(t.analog[column][i]) > threshold) {
      if (first < 0) first = i;
      last = i;
    }
  if (first < 0)
    throw TrialFormatError(t.source, t.marker_header_line, 0,
                           "force column '" + t.analog_names[column] + "' never exceeds " + std::to_string(threshold) +
                               " N: no rolling phase (eq. 4.5)");
  return {first, last};
}

std::pair<int, int> phase_from_kinematics(const AnkleSeries& a, double max_speed) {
  const int n = a.samples();
  int lowest = -1;
  for (int i = 0; i < n; ++i)
    if (a.present(i) && (lowest < 0 || a.height(i) < a.height(lowest))) lowest = i;
  // Speed of sample i from its central (one-sided at the ends) difference.
  auto slow = [&](int i) {
    const int p = std::max(i - 1, 0), q = std::min(i + 1, n - 1);
    return a.present(p) && a.present(q) && (a.position[q] - a.position[p]).norm() / (a.time[q] - a.time[p]) <= max_speed;
  };
  int first = lowest, last = lowest;
  while (first > 0 && slow(first - 1)) --first;
  while (last + 1 < n && slow(last + 1)) ++last;
  return {first, last};
}

}  // namespace

AnkleTrack sagittal_track(const AnkleSeries& a, int first, int last, const std::string& source,
                          std::optional<double> direction) {
  const auto [h1, h2] = horizontal_axes(a.vertical_axis);
  AnkleTrack track;
  track.source = source;
  track.first_sample = first;
  track.last_sample = last;
  std::vector<Eigen::Vector2d> horizontal;
  for (int i = first; i <= last; ++i) {
    if (!a.present(i)) throw std::invalid_argument(source + ": the ankle is missing in " + a.frames(i, i));
    horizontal.emplace_back(a.position[i][h1], a.position[i][h2]);
  }
  track.direction_estimated = !direction;
  track.walking_direction = direction ? *direction : walking_direction(horizontal);  // eq. (4.3)
  const Eigen::Vector2d e(std::cos(track.walking_direction), std::sin(track.walking_direction));
  for (int i = first; i <= last; ++i) {
    track.time.push_back(a.time[i]);
    track.x.push_back(horizontal[i - first].dot(e));
    track.z.push_back(a.height(i));
  }
  return track;
}

AnkleTrack stance_track(const GaitTrial& trial, int k, double start_shift, double end_shift) {
  const AnkleSeries& a = trial.ankle;
  const Stance& s = trial.stances.at(k);
  if (!s.complete()) throw std::invalid_argument(a.source + " stance " + std::to_string(k + 1) + ": " + s.refusal);
  int first = s.first, last = s.last;
  while (first > 0 && a.present(first - 1) && a.time[first - 1] >= s.start + start_shift - 1e-9) --first;
  while (first < last && a.time[first] < s.start + start_shift - 1e-9) ++first;
  while (last + 1 < a.samples() && a.present(last + 1) && a.time[last + 1] <= s.end + end_shift + 1e-9) ++last;
  while (last > first && a.time[last] > s.end + end_shift + 1e-9) --last;
  char name[64];
  std::snprintf(name, sizeof name, " stance %d (%.3f-%.3f s)", k + 1, s.start, s.end);
  AnkleTrack t = sagittal_track(a, first, last, a.source + name, a.walking_direction);
  t.direction_estimated = a.direction_estimated;
  t.phase_rule = s.rule;
  return t;
}

std::vector<AnkleTrack> stance_tracks(const std::vector<GaitTrial>& trials, double start_shift, double end_shift) {
  std::vector<AnkleTrack> tracks;
  for (const GaitTrial& t : trials)
    for (std::size_t k = 0; k < t.stances.size(); ++k)
      if (t.stances[k].complete()) {
        const bool contact = t.stances[k].contact;
        tracks.push_back(stance_track(t, static_cast<int>(k), contact ? std::max(start_shift, 0.0) : start_shift,
                                      contact ? std::min(end_shift, 0.0) : end_shift));
      }
  return tracks;
}

AnkleTrack ankle_track(const MarkerTrial& t, const AnkleTrackOptions& o) {
  AnkleSeriesOptions so;
  so.markers = o.markers;
  so.vertical_axis = o.vertical_axis;
  so.ground_height = o.ground_height;
  so.max_gap = 0.0;
  const AnkleSeries a = ankle_series(t, so);
  const int n = t.samples();
  std::pair<int, int> phase{0, n - 1};
  std::string rule;
  const int force = t.analog_index(o.force_column);
  if (o.interval) {
    phase = frames_within(a, o.interval->first, o.interval->second);
    rule = "interval";
  } else if (force >= 0) {
    phase = phase_from_force(t, force, o.force_threshold);  // eq. (4.5)
    rule = "force column " + o.force_column;
  } else {
    phase = phase_from_kinematics(a, o.max_rolling_speed);
    rule = "kinematics";
  }
  if (phase.first < 0 || phase.second - phase.first + 1 < o.min_samples)
    throw TrialFormatError(t.source, t.marker_header_line, 0,
                           "rolling phase (" + rule + ") has " + std::to_string(phase.first < 0 ? 0 : phase.second - phase.first + 1) +
                               " samples, at least " + std::to_string(o.min_samples) + " needed");
  for (int i = phase.first; i <= phase.second; ++i)
    if (!a.present(i))
      throw TrialFormatError(t.source, t.line_of_sample[i], 0, "rolling phase (" + rule + "): the ankle marker(s) missing in " + a.frames(i, i));
  AnkleTrack track = sagittal_track(a, phase.first, phase.second, t.source, o.walking_direction);
  track.phase_rule = rule;
  return track;
}

}  // namespace cyclopt::foot_fit
