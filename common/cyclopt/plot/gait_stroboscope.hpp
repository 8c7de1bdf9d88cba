#pragma once
// Stroboscope of a periodic gait (seed 001 Fig. 9.2): stick figures with the true foot outlines at
// equidistant times, each where it is (a physical x axis: x = 0 at the stance ankle at the
// impact that starts the step), the ground, the rolling contact point of every frame and the path
// of the swing foot's lowest point (its clearance). The stored gait is one step; step k is the
// same motion shifted by k step lengths with the legs' roles swapped. Later poses are drawn darker.

#include "cyclopt/plot/scene.hpp"
#include "cyclopt/plot/walker_job_results.hpp"

namespace cyclopt::plot {

struct StroboscopeOptions {
  int steps = 1;
  int frames_per_step = 6;  // intervals per step: 7 equidistant times per step as in Fig. 9.2
  // false: a panel for a row of them (the report's): no legend (the text beside it explains the
  // colours), the title only the speed.
  bool legend = true;
};

// `point`: a converged gait of `job` with its trajectory (point_near()).
Scene gait_stroboscope(const WalkerJobResults& job, const GaitPoint& point, const StroboscopeOptions& options = {});

}  // namespace cyclopt::plot
