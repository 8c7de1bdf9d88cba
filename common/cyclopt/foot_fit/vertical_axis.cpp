#include "cyclopt/foot_fit/vertical_axis.hpp"

#include <algorithm>
#include <array>
#include <cstdio>

namespace cyclopt::foot_fit {
namespace {

constexpr double kClearMargin = 1.5;    // the winning extent or range exceeds the next by this factor
constexpr double kBodyExtent = 0.5;     // m: a frame's markers span at least this vertically (above the ankles)
constexpr int kMinMarkersPerFrame = 3;

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// Axes ordered by decreasing value.
std::array<int, 3> ranked(const std::array<double, 3>& v) {
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return v[a] > v[b]; });
  return order;
}

std::string metres(const std::array<double, 3>& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "x %.2f m, y %.2f m, z %.2f m", v[0], v[1], v[2]);
  return buf;
}

}  // namespace

VerticalAxisEstimate estimate_vertical_axis(const MarkerTrial& t, const std::vector<int>& ankle_markers) {
  VerticalAxisEstimate e;
  // Cue 1: median over frames of each axis' extent across the markers present in the frame.
  std::array<std::vector<double>, 3> extents;
  for (int i = 0; i < t.samples(); ++i) {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    int present = 0;
    for (std::size_t m = 0; m < t.positions.size(); ++m)
      if (t.present(static_cast<int>(m), i)) {
        lo = lo.cwiseMin(t.positions[m][i]);
        hi = hi.cwiseMax(t.positions[m][i]);
        ++present;
      }
    if (present >= kMinMarkersPerFrame)
      for (int a = 0; a < 3; ++a) extents[a].push_back(hi[a] - lo[a]);
  }
  const std::array<double, 3> body{median(extents[0]), median(extents[1]), median(extents[2])};
  const std::array<int, 3> by_body = ranked(body);
  const bool body_applies = body[by_body[0]] >= kBodyExtent;
  const bool body_clear = body[by_body[0]] >= kClearMargin * body[by_body[1]];
  // Cue 2: the ankle's ranges; the longest is the walking direction, the larger other one is up.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  int present = 0;
  for (int i = 0; i < t.samples(); ++i) {
    Eigen::Vector3d ankle = Eigen::Vector3d::Zero();
    bool all = true;
    for (int m : ankle_markers) {
      all = all && t.present(m, i);
      ankle += t.positions[m][i];
    }
    if (!all) continue;
    ankle /= double(ankle_markers.size());
    lo = lo.cwiseMin(ankle);
    hi = hi.cwiseMax(ankle);
    ++present;
  }
  const std::array<double, 3> range{present ? hi[0] - lo[0] : 0.0, present ? hi[1] - lo[1] : 0.0,
                                    present ? hi[2] - lo[2] : 0.0};
  const std::array<int, 3> by_range = ranked(range);
  const int ankle_axis = by_range[1];
  const bool ankle_clear = present > 1 && range[by_range[1]] >= kClearMargin * range[by_range[2]];
  e.evidence = "ankle ranges " + metres(range);
  if (body_applies) e.evidence += "; median extent of a frame's markers " + metres(body);
  if (body_applies) {
    e.axis = by_body[0];
    e.decided = body_clear && (!ankle_clear || ankle_axis == e.axis);
  } else {
    e.axis = ankle_axis;
    e.decided = ankle_clear;
  }
  return e;
}

}  // namespace cyclopt::foot_fit
