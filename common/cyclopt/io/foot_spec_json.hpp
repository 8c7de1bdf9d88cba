#pragma once
// A foot specification as users write it (JSON), with strict validation.
//
// JSON form (SI units: metres, radians, kg/m^2):
//   {"model": "HMT", "h_F": 0.1065, "l_HA": 0.0765, "l_HM": 0.2486, "l_MT": 0.1124,
//    "gamma_F": 0.768, "k_H": 1e-8, "k_HM": 0.054, "k_MT": 0.1, "k_T": 1e-8,
//    "periodic_terms": 0, "density": 36.9, "theta_F0": 2.246, "name": "P2 shoes left"}
// Parameter names and ranges: parameter_layout() in foot/foot_parameters.hpp (also
// proto/schemas/foot.schema.json). Optional: periodic_terms (eq. 3.18, 0-8, default 0),
// density (appendix E; mass properties from geometry), theta_F0 (rad, default: eq. E.7 when a
// density is given), name. Unknown keys are errors.

#include "cyclopt/foot/foot_spec.hpp"

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace cyclopt::io {

// Parses and validates (foot::validate); `path` prefixes field names in SpecError messages.
foot::FootSpec foot_spec_from_json(const nlohmann::json& j, const std::string& path = "foot");
// A foot as a job spec gives it: a preset name (foot/foot_presets.hpp) or a foot spec object.
foot::FootSpec foot_value(const nlohmann::json& v, const std::string& path = "foot");
nlohmann::json to_json(const foot::FootSpec& spec);

}  // namespace cyclopt::io
