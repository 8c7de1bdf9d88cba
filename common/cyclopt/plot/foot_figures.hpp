#pragma once
// Figures of a foot geometry (seed 001, Fig. 3.5): (a) the regularised outline with its
// generating polygon, ankle and centre of mass; (b) the ankle trajectory while rolling, beside
// the polygon's piecewise-circular one.

#include "cyclopt/foot/foot_spec.hpp"
#include "cyclopt/plot/line_chart.hpp"
#include "cyclopt/plot/scene.hpp"

namespace cyclopt::plot {

// Outline points of the foot over one full turn, in the foot frame (m).
std::vector<std::array<double, 2>> foot_outline(const foot::FootSpec& spec);

Scene foot_shape_scene(const foot::FootSpec& spec);
LineChart ankle_trajectory_chart(const foot::FootSpec& spec);

}  // namespace cyclopt::plot
