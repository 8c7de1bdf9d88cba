#pragma once
// Animated SVG of a periodic gait (seed 001 Fig. 9.2 in motion): the walker's torso, legs and feet
// over two steps in real time, looping. Pure SVG: every body part is one <polyline> or <polygon>
// whose `points` an SMIL <animate> steps through the poses (no JavaScript), so it plays inline in
// the HTML report. Step k is the stored step shifted by k step lengths with the legs' roles swapped.
// Drawn 230 px high, small enough for the report to set several side by side in a grid (the gait's
// speed, step length and period go in the grid's caption, once); above the walker a clock
// "t = ... s" (id "gait-clock") counting the time since the loop began, below the ground a bar (id
// "gait-time-bar") filling over the loop, marked at 0, T and 2 T.

#include "cyclopt/plot/walker_job_results.hpp"

#include <string>

namespace cyclopt::plot {

// `point`: a converged gait of `job` with its trajectory; `frames_per_step` >= 1 poses per step,
// interpolated linearly by the browser in between. Throws std::invalid_argument otherwise.
std::string gait_animation_svg(const WalkerJobResults& job, const GaitPoint& point, int frames_per_step = 24);

}  // namespace cyclopt::plot
