#pragma once
// Parameter grids as users write them: "lo:step:hi" (hi included when it lies on the grid
// within a relative 1e-9 of the step count, and then exactly hi; every point the double of its
// decimal value, "0.3:0.1:2.3" holds 0.6, not 0.6000000000000001), a single number, or a JSON
// array of numbers. Used for "speeds" and for the foot_sweep "values".

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace cyclopt::service {

inline constexpr int kMaxGridPoints = 10000;

// Every value must lie in [lo, hi]; at most kMaxGridPoints values. Throws SpecError naming
// `path`.
std::vector<double> parse_value_range(const nlohmann::json& v, const std::string& path, double lo, double hi);

}  // namespace cyclopt::service
