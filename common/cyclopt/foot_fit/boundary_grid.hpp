#pragma once
// The moved stance boundaries behind the boundary spread (fit_spread.hpp): the data sets it
// refits, one per distinct set of stance windows.
//
// A boundary sits on a frame: stance_track puts a start moved by s on the first frame at or after
// it and an end moved by s on the last frame at or before it (to 1 ns), so a shift changes a
// stance's window only where it puts that boundary on a frame. The every-frame grid (steps 0)
// tries each such shift within +-tolerance, and +-tolerance themselves; so every window that any
// start and end shift within the tolerance gives is among its data sets, and a check on any finer
// grid of shifts (1 ms, 5 ms) lands on windows the spread refitted. The one exception is of
// rounding width: where the frame offsets of two stances differ by less than that 1 ns without
// being equal, the shifts between them (an interval of ~1e-16 s) are not tried.

#include "cyclopt/foot_fit/ankle_track.hpp"
#include "cyclopt/foot_fit/stances.hpp"

#include <utility>
#include <vector>

namespace cyclopt::foot_fit {

// The [first_sample, last_sample] of each track: what a data set of stances is identified by.
using StanceWindows = std::vector<std::pair<int, int>>;
StanceWindows stance_windows(const std::vector<AnkleTrack>& tracks);

// The shifts (s) a boundary is moved by, 0 first, then later ones outwards, then earlier ones
// outwards. steps 0: every shift within +-tolerance that puts the start or the end of a complete
// stance on a frame, and +-tolerance; steps n >= 1: the grid {0, +-tolerance/n, ..., +-tolerance}.
std::vector<double> boundary_shifts(const std::vector<GaitTrial>& trials, double tolerance, int steps);

struct MovedBoundaries {
  double start_shift = 0.0, end_shift = 0.0;  // s
  std::vector<AnkleTrack> tracks;
};

// Every distinct data set of stance_tracks (ankle_track.hpp) over start and end shifts from boundary_shifts,
// but the unmoved one, each once under the first shift pair that gives it; inward shifts come
// first, so a plate's shrunk stances are named by the shifts that made them.
std::vector<MovedBoundaries> boundary_grid(const std::vector<GaitTrial>& trials, double tolerance, int steps);

}  // namespace cyclopt::foot_fit
