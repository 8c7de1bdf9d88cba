#pragma once
// Figures of a foot fit (seed 001, Fig. 4.3 / 4.4): (a) the measured ankle points of all trials
// against the model's points at the fitted foot angles and the model's ankle trajectory; (b) the
// fitted outline with its generating polygon, the part that rolled in the fit drawn bold.

#include "cyclopt/foot_fit/ankle_track.hpp"
#include "cyclopt/foot_fit/rolling_foot_fit.hpp"
#include "cyclopt/plot/scene.hpp"

#include <vector>

namespace cyclopt::plot {

// (a): x of every trial relative to its fitted offset x_off,k, so the trials overlay.
Scene fitted_ankle_scene(const std::vector<foot_fit::AnkleTrack>& tracks, const foot_fit::FootFitResult& fit);
// (b)
Scene fitted_outline_scene(const foot_fit::FootFitResult& fit);

}  // namespace cyclopt::plot
