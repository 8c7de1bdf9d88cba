#include "cyclopt/foot_fit/boundary_grid.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace cyclopt::foot_fit {

StanceWindows stance_windows(const std::vector<AnkleTrack>& tracks) {
  StanceWindows w;
  for (const AnkleTrack& t : tracks) w.emplace_back(t.first_sample, t.last_sample);
  return w;
}

std::vector<double> boundary_shifts(const std::vector<GaitTrial>& trials, double tolerance, int steps) {
  if (!(tolerance >= 0.0) || steps < 0)
    throw std::invalid_argument("boundary shifts: tolerance " + std::to_string(tolerance) + " s or steps " + std::to_string(steps) +
                                " is negative");
  std::vector<double> shifts{0.0, tolerance, -tolerance};
  if (steps > 0) {
    for (int i = 1; i < steps; ++i) {
      shifts.push_back(tolerance * i / steps);
      shifts.push_back(-tolerance * i / steps);
    }
  } else {
    for (const GaitTrial& t : trials)
      for (const Stance& s : t.stances)
        if (s.complete())
          for (double frame : t.ankle.time)
            for (double boundary : {s.start, s.end})
              if (std::abs(frame - boundary) <= tolerance) shifts.push_back(frame - boundary);
  }
  // 0, then the later shifts from the smallest, then the earlier ones from the smallest.
  std::sort(shifts.begin(), shifts.end(), [](double a, double b) {
    return (a < 0.0) != (b < 0.0) ? b < 0.0 : std::abs(a) < std::abs(b);
  });
  shifts.erase(std::unique(shifts.begin(), shifts.end()), shifts.end());
  return shifts;
}

std::vector<MovedBoundaries> boundary_grid(const std::vector<GaitTrial>& trials, double tolerance, int steps) {
  const std::vector<double> starts = boundary_shifts(trials, tolerance, steps);
  // Inward for an end is earlier: 0, then the earlier shifts, then the later ones.
  std::vector<double> ends{0.0};
  for (double s : starts)
    if (s < 0.0) ends.push_back(s);
  for (double s : starts)
    if (s > 0.0) ends.push_back(s);
  std::set<StanceWindows> seen{stance_windows(stance_tracks(trials))};
  std::vector<MovedBoundaries> grid;
  for (double start : starts)
    for (double end : ends) {
      std::vector<AnkleTrack> tracks = stance_tracks(trials, start, end);
      if (seen.insert(stance_windows(tracks)).second) grid.push_back({start, end, std::move(tracks)});
    }
  return grid;
}

}  // namespace cyclopt::foot_fit
