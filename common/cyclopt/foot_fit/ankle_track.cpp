#include "cyclopt/foot_fit/ankle_track.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <stdexcept>

namespace cyclopt::foot_fit {
namespace {

struct Axes {
  int vertical, first, second;
};

Axes axes_of(int vertical) {
  if (vertical < 0 || vertical > 2) throw std::invalid_argument("vertical_axis: " + std::to_string(vertical) + " is not in 0..2");
  return {vertical, vertical == 0 ? 1 : 0, vertical == 2 ? 1 : 2};
}

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

std::pair<int, int> phase_from_kinematics(const MarkerTrial& t, const std::vector<Eigen::Vector3d>& ankle, int vertical,
                                          double max_speed) {
  const int n = t.samples();
  int lowest = 0;
  for (int i = 1; i < n; ++i)
    if (ankle[i][vertical] < ankle[lowest][vertical]) lowest = i;
  // Speed of sample i from its central (one-sided at the ends) difference.
  auto speed = [&](int i) {
    const int a = std::max(i - 1, 0), b = std::min(i + 1, n - 1);
    return (ankle[b] - ankle[a]).norm() / (t.time[b] - t.time[a]);
  };
  int first = lowest, last = lowest;
  while (first > 0 && speed(first - 1) <= max_speed) --first;
  while (last + 1 < n && speed(last + 1) <= max_speed) ++last;
  return {first, last};
}

}  // namespace

double walking_direction(const std::vector<Eigen::Vector2d>& h) {
  if (h.size() < 2) throw std::invalid_argument("walking direction: needs at least two ankle positions");
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : h) mean += p;
  mean /= double(h.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const auto& p : h) scatter += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(scatter);
  Eigen::Vector2d axis = eig.eigenvectors().col(1);
  if (axis.dot(h.back() - h.front()) < 0) axis = -axis;
  return std::atan2(axis.y(), axis.x());
}

AnkleTrack ankle_track(const MarkerTrial& t, const AnkleTrackOptions& o) {
  if (o.markers.empty() || o.markers.size() > 2)
    throw std::invalid_argument("markers: give one ankle marker or the two malleolus markers (eq. 4.1), got " +
                                std::to_string(o.markers.size()));
  const Axes ax = axes_of(o.vertical_axis);
  std::vector<int> index;
  for (const std::string& name : o.markers) index.push_back(t.marker_index(name));
  const int n = t.samples();
  std::vector<Eigen::Vector3d> ankle(n, Eigen::Vector3d::Zero());
  for (int i = 0; i < n; ++i) {
    for (int m : index) ankle[i] += t.positions[m][i];
    ankle[i] /= double(index.size());  // eq. (4.1)
  }
  AnkleTrack track;
  track.source = t.source;
  std::pair<int, int> phase{0, n - 1};
  const int force = t.analog_index(o.force_column);
  if (o.interval) {
    if (!(o.interval->first < o.interval->second))
      throw std::invalid_argument("interval: start " + std::to_string(o.interval->first) + " s is not before end " +
                                  std::to_string(o.interval->second) + " s");
    int first = -1, last = -1;
    for (int i = 0; i < n; ++i)
      if (t.time[i] >= o.interval->first && t.time[i] <= o.interval->second) {
        if (first < 0) first = i;
        last = i;
      }
    phase = {first, last};
    track.phase_rule = "interval";
  } else if (force >= 0) {
    phase = phase_from_force(t, force, o.force_threshold);  // eq. (4.5)
    track.phase_rule = "force column " + o.force_column;
  } else if (n > 0) {
    phase = phase_from_kinematics(t, ankle, ax.vertical, o.max_rolling_speed);
    track.phase_rule = "kinematics";
  }
  if (phase.first < 0 || phase.second - phase.first + 1 < o.min_samples)
    throw TrialFormatError(t.source, t.marker_header_line, 0,
                           "rolling phase (" + (track.phase_rule.empty() ? std::string("empty file") : track.phase_rule) +
                               ") has " + std::to_string(phase.first < 0 ? 0 : phase.second - phase.first + 1) +
                               " samples, at least " + std::to_string(o.min_samples) + " needed");
  track.first_sample = phase.first;
  track.last_sample = phase.second;
  std::vector<Eigen::Vector2d> horizontal;
  for (int i = phase.first; i <= phase.second; ++i) horizontal.emplace_back(ankle[i][ax.first], ankle[i][ax.second]);
  track.direction_estimated = !o.walking_direction;
  track.walking_direction = o.walking_direction ? *o.walking_direction : walking_direction(horizontal);  // eq. (4.3)
  const Eigen::Vector2d e(std::cos(track.walking_direction), std::sin(track.walking_direction));
  for (int i = phase.first; i <= phase.second; ++i) {
    track.time.push_back(t.time[i]);
    track.x.push_back(horizontal[i - phase.first].dot(e));
    track.z.push_back(ankle[i][ax.vertical] - o.ground_height);
  }
  return track;
}

}  // namespace cyclopt::foot_fit
