#include "cyclopt/foot/foot_presets.hpp"

#include <array>
#include <utility>
#include <vector>

namespace cyclopt::foot {
namespace {

// The preset names used before the catalogue existed (all fitted to the SG trajectory).
constexpr std::array<std::pair<std::string_view, std::string_view>, 3> kAliases{{
    {"P2-shoes-left-HMT", "P2-shoes-left-HMT-SG"},
    {"P1-barefoot-left-HM", "P1-barefoot-left-HM-SG"},
    {"P1-shoes-left-HMT", "P1-shoes-left-HMT-SG"},
}};

FootPreset point_preset() {
  FootPreset p;
  p.name = "point";
  p.source = "seed 001 Table D.1 (point feet)";
  p.spec.model = FootModel::point;
  p.spec.parameters.resize(0);
  p.spec.name = "point foot";
  return p;
}

std::vector<FootPreset> build_presets() {
  std::vector<FootPreset> all{point_preset()};
  for (const FittedFoot& f : fitted_feet()) {
    FootPreset p;
    p.name = f.name();
    p.source = f.source();
    p.spec = f.spec;
    p.fitted = &f;
    for (const auto& [alias, target] : kAliases)
      if (target == p.name) p.alias = alias;
    all.push_back(std::move(p));
  }
  return all;
}

const std::vector<FootPreset>& presets() {
  static const std::vector<FootPreset> all = build_presets();
  return all;
}

}  // namespace

std::span<const FootPreset> foot_presets() { return presets(); }

const FootPreset& foot_preset(std::string_view name) {
  for (const FootPreset& p : presets())
    if (p.name == name || (!p.alias.empty() && p.alias == name)) return p;
  std::string aliases;
  for (const auto& [alias, target] : kAliases) aliases += ", " + std::string(alias);
  throw SpecError("preset", "unknown foot preset '" + std::string(name) +
                                "'; known: point and the seed's fitted feet SUBJECT-FOOTWEAR-SIDE-MODEL-TRAJECTORY "
                                "(SUBJECT P1-P9, FOOTWEAR barefoot|shoes, SIDE left|right, MODEL HM|HMT, "
                                "TRAJECTORY SG|AK|IK, e.g. P3-shoes-left-HM-SG; cyclopt-foot --list-presets), "
                                "aliases" + aliases.substr(1));
}

}  // namespace cyclopt::foot
