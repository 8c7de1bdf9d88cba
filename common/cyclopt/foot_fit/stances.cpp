#include "cyclopt/foot_fit/stances.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace cyclopt::foot_fit {
namespace {

std::string fixed(double v, int digits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// Whether missing frame i belongs to the ankle's absence before its first or after its last frame.
bool before_data(const AnkleSeries& a, int i) {
  for (int k = i; k >= 0; --k)
    if (a.present(k)) return false;
  return true;
}
bool after_data(const AnkleSeries& a, int i) {
  for (int k = i; k < a.samples(); ++k)
    if (a.present(k)) return false;
  return true;
}

// The stance [first, last] with its checks: missing ankle frames (cut by the recording or an
// unfilled gap) and too few frames.
Stance checked(const AnkleSeries& a, int first, int last, std::string rule, const StanceOptions& o) {
  Stance s{first, last, a.time[first], a.time[last], std::move(rule), false, {}};
  int gap_first = -1, gap_last = -1;
  for (int i = first; i <= last; ++i)
    if (!a.present(i)) {
      if (gap_first < 0) gap_first = i;
      gap_last = i;
    }
  if (gap_first >= 0) {
    if (before_data(a, gap_first))
      s.refusal = "cut by the start of the ankle markers' data (their first frame: " + a.frames(gap_last + 1, gap_last + 1) +
                  "; the foot may have been on the ground before)";
    else if (after_data(a, gap_last))
      s.refusal = "cut by the end of the ankle markers' data (their last frame: " + a.frames(gap_first - 1, gap_first - 1) +
                  "; the foot may have stayed on the ground after)";
    else
      s.refusal = "ankle markers missing (" + a.frames(gap_first, gap_last) + ", longer than the " + fixed(1e3 * a.max_gap, 0) +
                  " ms a gap may be filled)";
  } else if (last - first + 1 < o.min_samples) {
    s.refusal = "too short (" + std::to_string(last - first + 1) + " frames, at least " + std::to_string(o.min_samples) + " needed)";
  }
  return s;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}  // namespace

int GaitTrial::complete_stances() const {
  return static_cast<int>(std::count_if(stances.begin(), stances.end(), [](const Stance& s) { return s.complete(); }));
}

std::vector<Stance> force_stances(const AnkleSeries& a, const std::vector<ForceChannel>& channels, bool by_cop,
                                  const StanceOptions& o) {
  std::vector<Stance> out;
  const int n = a.samples();
  for (const ForceChannel& c : channels) {
    std::vector<double> f(n);
    for (int i = 0; i < n; ++i) f[i] = c.vertical_at(a.time[i]);
    for (int i = 0; i < n;) {
      if (!(std::abs(f[i]) > o.force_threshold)) {
        ++i;
        continue;
      }
      int j = i;
      while (j + 1 < n && std::abs(f[j + 1]) > o.force_threshold) ++j;
      const int first = i, last = j;
      i = j + 1;
      if (by_cop && !c.cop.empty()) {
        std::vector<double> d;
        for (int k = first; k <= last; ++k) {
          Eigen::Vector3d r = c.cop_at(a.time[k]) - a.position[k];
          r[a.vertical_axis] = 0.0;
          if (r.allFinite()) d.push_back(r.norm());
        }
        if (d.empty() || median(d) > o.max_cop_distance) continue;  // another foot on this plate
      }
      Stance s = checked(a, first, last, "force " + c.name, o);
      s.contact = true;
      if (s.complete() && (first == 0 || std::isnan(f[first - 1])))
        s.refusal = "cut by the start of the force recording (" + c.name + " loaded at " + fixed(a.time[first], 3) +
                    " s; the foot may have been on the ground before)";
      if (s.complete() && (last == n - 1 || std::isnan(f[last + 1])))
        s.refusal = "cut by the end of the force recording (" + c.name + " loaded at " + fixed(a.time[last], 3) +
                    " s; the foot may have stayed on the ground after)";
      out.push_back(std::move(s));
    }
  }
  std::sort(out.begin(), out.end(), [](const Stance& x, const Stance& y) { return x.first < y.first; });
  return out;
}

std::vector<Stance> kinematic_stances(const AnkleSeries& a, const StanceOptions& o) {
  const int n = a.samples();
  std::vector<double> speed(n, std::nan(""));  // central differences where both neighbours exist
  for (int i = 1; i + 1 < n; ++i)
    if (a.present(i - 1) && a.present(i) && a.present(i + 1))
      speed[i] = (a.position[i + 1] - a.position[i - 1]).norm() / (a.time[i + 1] - a.time[i - 1]);
  std::vector<Stance> out;
  for (int i = 0; i < n;) {
    if (!(speed[i] < o.max_rolling_speed)) {
      ++i;
      continue;
    }
    int j = i;
    while (j + 1 < n && speed[j + 1] < o.max_rolling_speed) ++j;
    const int first = i, last = j;
    i = j + 1;
    if (*std::min_element(speed.begin() + first, speed.begin() + last + 1) >= o.still_speed) continue;  // no flat foot
    Stance s = checked(a, first, last, "kinematics", o);
    // A run ends where the ankle speeds up; one that ends because the speed is unknown (no frame
    // or no ankle beyond it) is cut by the recording or a gap.
    if (s.complete() && (first == 0 || std::isnan(speed[first - 1])))
      s.refusal = std::string(first <= 1 || before_data(a, first - 2) ? "cut by the start of the ankle markers' data"
                                                                       : "cut by a gap in the ankle markers") +
                  " (before " + a.frames(first, first) + "; the foot may have been on the ground before)";
    if (s.complete() && (last == n - 1 || std::isnan(speed[last + 1])))
      s.refusal = std::string(last >= n - 2 || after_data(a, last + 2) ? "cut by the end of the ankle markers' data"
                                                                       : "cut by a gap in the ankle markers") +
                  " (after " + a.frames(last, last) + "; the foot may have stayed on the ground after)";
    out.push_back(std::move(s));
  }
  return out;
}

std::pair<int, int> frames_within(const AnkleSeries& a, double t0, double t1) {
  if (!(t0 < t1))
    throw std::invalid_argument("interval: start " + fixed(t0, 4) + " s is not before end " + fixed(t1, 4) + " s");
  int first = -1, last = -1;
  for (int i = 0; i < a.samples(); ++i)
    if (a.time[i] >= t0 && a.time[i] <= t1) {
      if (first < 0) first = i;
      last = i;
    }
  return {first, last};
}

Stance interval_stance(const AnkleSeries& a, double t0, double t1, const StanceOptions& o) {
  const auto [first, last] = frames_within(a, t0, t1);
  if (first < 0) {
    Stance s;
    s.start = t0;
    s.end = t1;
    s.rule = "interval";
    s.refusal = "no frame (in " + fixed(t0, 3) + "-" + fixed(t1, 3) + " s)";
    return s;
  }
  return checked(a, first, last, "interval", o);
}

}  // namespace cyclopt::foot_fit
