#pragma once
// Named feet: the point foot of Table D.1 and every fitted foot of the seed's catalogue (seed 001,
// Table 4.2 and appendix B; fitted_feet.hpp), so users and tests can refer to "the P1 barefoot
// foot" without retyping tables. Fitted feet are named SUBJECT-FOOTWEAR-SIDE-MODEL-TRAJECTORY
// (e.g. "P3-shoes-left-HM-SG"); the names of the first presets (without the trajectory) stay
// valid as aliases of their SG feet.

#include "cyclopt/foot/fitted_feet.hpp"
#include "cyclopt/foot/foot_spec.hpp"

#include <span>
#include <string>
#include <string_view>

namespace cyclopt::foot {

struct FootPreset {
  std::string name;    // e.g. "P1-barefoot-left-HM-SG"
  std::string alias;   // an older name of the same foot, e.g. "P1-barefoot-left-HM"; may be empty
  std::string source;  // table of the seed
  FootSpec spec;
  const FittedFoot* fitted = nullptr;  // its catalogue entry; null for the point foot
};

// All presets: "point" first, then the catalogue in the seed's table order.
std::span<const FootPreset> foot_presets();
// By name or alias. Throws SpecError (field "preset") explaining the naming scheme if unknown.
const FootPreset& foot_preset(std::string_view name);

}  // namespace cyclopt::foot
