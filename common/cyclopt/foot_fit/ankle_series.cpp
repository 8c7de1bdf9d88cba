#include "cyclopt/foot_fit/ankle_series.hpp"

#include "cyclopt/foot_fit/vertical_axis.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace cyclopt::foot_fit {

std::string AnkleSeries::frames(int first, int last) const {
  char buf[96];
  if (first == last)
    std::snprintf(buf, sizeof buf, "line %d at %.3f s", line_of_sample[first], time[first]);
  else
    std::snprintf(buf, sizeof buf, "lines %d-%d at %.3f-%.3f s", line_of_sample[first], line_of_sample[last], time[first],
                  time[last]);
  return buf;
}

AnkleSeries ankle_series(const MarkerTrial& t, const AnkleSeriesOptions& o) {
  if (o.markers.empty() || o.markers.size() > 2)
    throw std::invalid_argument("markers: give one ankle marker or the two malleolus markers (eq. 4.1), got " +
                                std::to_string(o.markers.size()));
  if (o.vertical_axis && (*o.vertical_axis < 0 || *o.vertical_axis > 2))
    throw std::invalid_argument("vertical_axis: " + std::to_string(*o.vertical_axis) + " is not in 0..2 (x, y, z)");
  if (!(o.max_gap >= 0.0 && o.max_gap <= 1.0))
    throw std::invalid_argument("max_gap: " + std::to_string(o.max_gap) + " s is not in [0, 1] s");
  std::vector<int> index;
  for (const std::string& name : o.markers) index.push_back(t.marker_index(name));
  AnkleSeries s;
  s.source = t.source;
  s.markers = o.markers;
  s.time = t.time;
  s.line_of_sample = t.line_of_sample;
  s.ground_height = o.ground_height;
  s.max_gap = o.max_gap;
  const int n = t.samples();
  s.position.assign(n, Eigen::Vector3d::Zero());
  for (int i = 0; i < n; ++i) {
    for (int m : index) s.position[i] += t.positions[m][i];  // NaN when a marker is missing
    s.position[i] /= double(index.size());                   // eq. (4.1)
  }
  std::string names;
  for (const std::string& m : o.markers) names += (names.empty() ? "" : " and ") + m;
  if (std::none_of(s.position.begin(), s.position.end(), [](const Eigen::Vector3d& p) { return p.allFinite(); }))
    throw TrialFormatError(t.source, t.marker_header_line, 0, names + ": no frame has the ankle marker(s)");
  // Gaps: runs of missing frames; interior ones up to max_gap are interpolated.
  for (int i = 0; i < n;) {
    if (s.present(i)) {
      ++i;
      continue;
    }
    int j = i;
    while (j + 1 < n && !s.present(j + 1)) ++j;
    AnkleGap g{i, j, false};
    if (i > 0 && j + 1 < n && s.time[j + 1] - s.time[i - 1] <= o.max_gap + 1e-9) {
      for (int k = i; k <= j; ++k) {
        const double a = (s.time[k] - s.time[i - 1]) / (s.time[j + 1] - s.time[i - 1]);
        s.position[k] = (1.0 - a) * s.position[i - 1] + a * s.position[j + 1];
      }
      g.filled = true;
    }
    s.gaps.push_back(g);
    i = j + 1;
  }
  const VerticalAxisEstimate e = estimate_vertical_axis(t, index);
  if (o.vertical_axis) {
    s.vertical_axis = *o.vertical_axis;
    s.vertical_rule = "given";
    if (e.decided && e.axis != s.vertical_axis)
      s.notes.push_back(std::string("the data suggest that ") + "xyz"[e.axis] + " points up, not the given " +
                        "xyz"[s.vertical_axis] + " (" + e.evidence + "); check --vertical-axis");
  } else {
    if (!e.decided)
      throw TrialFormatError(t.source, t.marker_header_line, 0,
                             "cannot tell which axis points up (" + e.evidence + "); give it with --vertical-axis x|y|z");
    s.vertical_axis = e.axis;
    s.vertical_rule = std::string("detected: ") + "xyz"[e.axis] + " (" + e.evidence + ")";
  }
  s.direction_estimated = !o.walking_direction;
  if (o.walking_direction) {
    s.walking_direction = *o.walking_direction;
  } else {
    const int h1 = s.vertical_axis == 0 ? 1 : 0, h2 = s.vertical_axis == 2 ? 1 : 2;
    std::vector<Eigen::Vector2d> path;
    for (int i = 0; i < n; ++i)
      if (s.present(i)) path.emplace_back(s.position[i][h1], s.position[i][h2]);
    s.walking_direction = walking_direction(path);  // eq. (4.2)-(4.3)
  }
  return s;
}

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

}  // namespace cyclopt::foot_fit
