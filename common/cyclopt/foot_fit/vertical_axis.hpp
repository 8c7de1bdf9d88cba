#pragma once
// Which axis of a marker file points up (against gravity). Gait labs use z-up (most .c3d
// exports) and y-up (OpenSim): a file read with the wrong one is fitted in the wrong plane.
//
// Two independent cues: (1) a standing or walking body is taller than it is long or wide, so
// across the markers of one frame the vertical extent is the largest (median over frames, when
// the file has markers above the ankles); (2) the ankle travels far along the walking direction,
// rises by a hand's breadth in every swing, and sways sideways by less, so among the two axes
// other than its longest range the vertical one has the larger range.

#include "cyclopt/foot_fit/marker_trial.hpp"

#include <string>
#include <vector>

namespace cyclopt::foot_fit {

struct VerticalAxisEstimate {
  int axis = 2;           // 0, 1, 2 = file x, y, z; meaningful when decided
  bool decided = false;   // the cues that apply agree, each by a clear margin
  std::string evidence;   // the cues' numbers, for messages
};

// From the frames' marker extents (all markers) and the ankle's ranges (the markers of
// `ankle_markers`, their mean per frame).
VerticalAxisEstimate estimate_vertical_axis(const MarkerTrial& trial, const std::vector<int>& ankle_markers);

}  // namespace cyclopt::foot_fit
