#pragma once
// A complete, machine-readable description of one foot: its specification, the derived polygon
// transitions, admissible angle range, mass properties (appendix E) and the rolling kinematics
// sampled over the admissible range. Used by the command-line foot report and the service.

#include "cyclopt/foot/foot_spec.hpp"

#include <nlohmann/json_fwd.hpp>

namespace cyclopt::foot {

struct FootReportOptions {
  int samples = 61;  // angles over the admissible range (>= 2)
};

// Builds the report. Mass properties appear when the spec has a density; theta_F0 is the
// spec's own or, failing that, the one from eq. (E.7).
nlohmann::json foot_report(const FootSpec& spec, const FootReportOptions& options = {});

// One sample of the rolling kinematics at foot angle theta (profile angle, before theta_F0).
nlohmann::json rolling_sample(const FootSpec& spec, double theta);

}  // namespace cyclopt::foot
