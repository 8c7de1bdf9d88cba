#pragma once
// Stroboscope of a giant swing (seed 000 Fig. 5.5, 25 Hz): the gymnast's two segments at
// equidistant times, re-simulated from a result of `cyclopt-giant-swing` (its task and the hip
// torque support values), with the bar and the paths of hip and feet.

#include "cyclopt/giant_swing/model.hpp"
#include "cyclopt/plot/scene.hpp"

#include <nlohmann/json.hpp>

namespace cyclopt::plot {

// Throws std::invalid_argument when `result` lacks "task" or "support_values_Nm".
Scene giant_swing_stroboscope(const giant_swing::Model& model, const nlohmann::json& result, double rate_hz = 25.0);

}  // namespace cyclopt::plot
