#pragma once
// The report of a foot_design job (`cyclopt report JOB`; seed 001 section 10.2): its resolved
// spec, one row per density (the design, its mass properties, active bounds (10.1), the optima
// per class, mean f_mech and the savings against the start foot and point feet, speeds reached,
// time per phase) and the figures of foot_design_figures.hpp, as one HTML page (html_report.hpp).

#include "cyclopt/plot/html_report.hpp"

#include <nlohmann/json.hpp>

namespace cyclopt::plot {

// `document`: the job as `cyclopt export` writes it. Throws std::invalid_argument for a job that
// is not a foot_design job or has no density stored yet.
Report foot_design_report(const nlohmann::json& document);

}  // namespace cyclopt::plot
