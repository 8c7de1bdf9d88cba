#pragma once
// A foot specification as users write it (JSON), with strict validation.
//
// JSON form (SI units: metres, radians, kg/m^2):
//   {"model": "HMT", "h_F": 0.1065, "l_HA": 0.0765, "l_HM": 0.2486, "l_MT": 0.1124,
//    "gamma_F": 0.768, "k_H": 1e-8, "k_HM": 0.054, "k_MT": 0.1, "k_T": 1e-8,
//    "periodic_terms": 0, "density": 36.9, "theta_F0": 2.246, "name": "P2 shoes left"}
// Parameter names and ranges: parameter_layout() in foot_parameters.hpp (also
// proto/schemas/foot.schema.json). Optional: periodic_terms (eq. 3.18, 0-8, default 0),
// density (appendix E; mass properties from geometry), theta_F0 (rad, default: eq. E.7 when a
// density is given), name. Unknown keys are errors.

#include "cyclopt/foot/foot_parameters.hpp"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <stdexcept>
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

// Thrown for an invalid specification; what() names the field (as a JSON path such as
// "foot.k_HM") and the admissible range or the reason.
class SpecError : public std::invalid_argument {
 public:
  SpecError(std::string field, const std::string& message);
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

inline constexpr int kMaxPeriodicTerms = 8;
inline constexpr double kMinDensity = 1e-6;    // kg/m^2
inline constexpr double kMaxDensity = 1000.0;  // kg/m^2

// Parses and validates; `path` prefixes field names in error messages.
FootSpec foot_spec_from_json(const nlohmann::json& j, const std::string& path = "foot");
nlohmann::json to_json(const FootSpec& spec);

// Checks a spec built in code (ranges, l_HA <= l_HM, HMT toe convexity); throws SpecError.
void validate(const FootSpec& spec, const std::string& path = "foot");

}  // namespace cyclopt::foot
