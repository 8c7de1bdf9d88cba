#pragma once
// The report of one walker job (`cyclopt report JOB`): its spec, state and timings, the table of
// solved points and every figure walker_figures() can draw from it, as one self-contained HTML
// page (html_report.hpp).

#include "cyclopt/plot/html_report.hpp"

#include <nlohmann/json.hpp>

namespace cyclopt::plot {

// `document`: the job as `cyclopt export` writes it. Throws std::invalid_argument for a job that
// is not a walker gait job.
Report walker_job_report(const nlohmann::json& document);

}  // namespace cyclopt::plot
