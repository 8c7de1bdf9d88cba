#pragma once
// A complete, machine-readable description of one foot: its specification, the derived polygon
// transitions, admissible angle range, mass properties (appendix E) and the rolling kinematics
// sampled over the admissible range, as JSON. Used by the command-line foot report and the
// service's foot sweep.

#include "cyclopt/foot/foot_spec.hpp"

#include <nlohmann/json_fwd.hpp>

namespace cyclopt::io {

struct FootReportOptions {
  int samples = 61;  // angles over the admissible range (>= 2)
};

// Builds the report. Mass properties appear when the spec has a density; theta_F0 is the
// spec's own or, failing that, the one from eq. (E.7).
nlohmann::json foot_report(const foot::FootSpec& spec, const FootReportOptions& options = {});

}  // namespace cyclopt::io
