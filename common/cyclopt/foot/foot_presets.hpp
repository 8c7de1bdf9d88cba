#pragma once
// Named feet from the seed's fits to human walking data (seed 001, chapter 4, appendix B), so
// users and tests can refer to "the P1 barefoot foot" without retyping tables.

#include "cyclopt/foot/foot_spec.hpp"

#include <span>
#include <string_view>

namespace cyclopt::foot {

struct FootPreset {
  std::string_view name;    // e.g. "P1-barefoot-left-HM"
  std::string_view source;  // table of the seed
  FootSpec spec;
};

// All presets; the first is the default foot of the README's main job.
std::span<const FootPreset> foot_presets();
// Throws SpecError naming the known presets if `name` is not one of them.
const FootPreset& foot_preset(std::string_view name);

}  // namespace cyclopt::foot
