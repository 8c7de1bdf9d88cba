#pragma once
// The report of one walker job (`cyclopt report JOB`), one self-contained HTML page
// (html_report.hpp): its provenance (job_provenance.hpp), the table of solved points, the solver's
// diagnostics of every stored point (point_diagnostics.hpp), every solution curve with the best
// envelope (seed 001 Fig. 9.1) and the other figures over speed (walker_figures.hpp), what happens
// within the step of one chosen speed (step_figures.hpp, Fig. 9.5), stroboscopes of the slowest,
// chosen and fastest gait side by side (Fig. 9.2) and a grid of gait animations.

#include "cyclopt/plot/html_report.hpp"

#include <nlohmann/json.hpp>

#include <limits>

namespace cyclopt::plot {

// `document`: the job as `cyclopt export` writes it; `speed` (m/s) chooses the gait of the
// within-step figures (NaN: the middle converged speed). Throws std::invalid_argument for a job
// that is not a walker gait job.
Report walker_job_report(const nlohmann::json& document, double speed = std::numeric_limits<double>::quiet_NaN());

}  // namespace cyclopt::plot
