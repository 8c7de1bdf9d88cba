#pragma once
// Figures of a foot fit (seed 001, Fig. 4.3 / 4.4): (a) the measured ankle points of all trials
// against the model's points at the fitted foot angles and the model's ankle trajectory; (b) the
// fitted outline with its generating polygon, the part that rolled in the fit drawn bold. Before
// the fit, per recording, the ankle's height over time with the stances found in it. Track k
// (a fitted stance) has colour palette(k) in all of them.

#include "cyclopt/foot_fit/ankle_track.hpp"
#include "cyclopt/foot_fit/rolling_foot_fit.hpp"
#include "cyclopt/foot_fit/stances.hpp"
#include "cyclopt/plot/scene.hpp"
#include "cyclopt/plot/walker_figures.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace cyclopt::plot {

// The ankle height of `trial` over time: fitted stances in the colours of their tracks (the
// first being track `first_track`), refused ones dashed with the reason in the legend.
LineChart stance_chart(const foot_fit::GaitTrial& trial, int first_track);
// stance_chart of each trial, stems fit_stances_1, fit_stances_2, ...
std::vector<Figure> stance_figures(const std::vector<foot_fit::GaitTrial>& trials);

// (a): x of every trial relative to its fitted offset x_off,k, so the trials overlay.
Scene fitted_ankle_scene(const std::vector<foot_fit::AnkleTrack>& tracks, const foot_fit::FootFitResult& fit);
// (b)
Scene fitted_outline_scene(const foot_fit::FootFitResult& fit);
// Both, as figures with stems fit_hm_ankle, fit_hm_outline (fit_hmt_... for HMT).
std::vector<Figure> fit_figures(const std::vector<foot_fit::AnkleTrack>& tracks, const foot_fit::FootFitResult& fit);

// The figures of a stored foot_fit job (jobs/foot/foot_fit_kind.cpp) from the document `cyclopt
// export` writes: the trials from its spec, each converged fit from its record and angles. A fit
// that did not converge is not drawn; with `not_drawn` it is listed there with its reason.
// Throws std::invalid_argument when the document is not a foot_fit job or holds no fit yet.
std::vector<Figure> foot_fit_job_figures(const nlohmann::json& document, std::vector<std::string>* not_drawn = nullptr);

}  // namespace cyclopt::plot
