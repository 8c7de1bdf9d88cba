#pragma once
// A foot specification: model, parameters (layout and ranges: parameter_layout() in
// foot_parameters.hpp), optional periodic terms (eq. 3.18), density (appendix E) and theta_F0,
// and its validation. Its JSON form (what users write) is read and written in
// io/foot_spec_json.hpp.

#include "cyclopt/errors/spec_error.hpp"
#include "cyclopt/foot/foot_parameters.hpp"

#include <optional>
#include <string>

namespace cyclopt::foot {

struct FootSpec {
  FootModel model = FootModel::point;
  FootParameters<double> parameters;  // layout: parameter_layout(model)
  int periodic_terms = 0;
  std::optional<double> density;      // rho (kg/m^2)
  std::optional<double> theta_F0;     // rad
  std::string name;
};

inline constexpr int kMaxPeriodicTerms = 8;
inline constexpr double kMinDensity = 1e-6;    // kg/m^2
inline constexpr double kMaxDensity = 1000.0;  // kg/m^2

// Checks a spec (ranges, l_HA <= l_HM, HMT toe convexity); throws SpecError whose field is
// `path` + "." + the parameter's name, e.g. "foot.k_HM".
void validate(const FootSpec& spec, const std::string& path = "foot");

}  // namespace cyclopt::foot
