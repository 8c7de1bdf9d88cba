#pragma once
// The report of any stored job (`cyclopt report JOB`): the walker gait jobs' report
// (walker_job_report.hpp), a foot design's (foot_design_report.hpp), a foot comparison's (its feet
// and savings, the f_mech chart with the envelope and the outlines), a foot fit's (its figures);
// any other job its provenance and per-point diagnostics. Every report opens with the job's
// provenance (job_provenance.hpp) and lists the solver diagnostics of every stored point
// (point_diagnostics.hpp).

#include "cyclopt/plot/html_report.hpp"

#include <nlohmann/json.hpp>

#include <limits>

namespace cyclopt::plot {

// `document`: the job as `cyclopt export` writes it; `speed`: see walker_job_report().
Report job_report(const nlohmann::json& document, double speed = std::numeric_limits<double>::quiet_NaN());

Report foot_comparison_report(const nlohmann::json& document);

}  // namespace cyclopt::plot
