#include "cyclopt/foot/foot_presets.hpp"

#include <numbers>
#include <string>
#include <vector>

namespace cyclopt::foot {
namespace {

constexpr double mm = 1e-3;
constexpr double deg = std::numbers::pi / 180.0;

FootSpec hm_spec(double k_h, double k_m, double k_hm, double h_f, double l_ha, double l_hm, std::string name) {
  FootSpec s;
  s.model = FootModel::hm;
  s.parameters.resize(hm::count);
  s.parameters << h_f * mm, l_ha * mm, l_hm * mm, k_h, k_hm, k_m;
  s.name = std::move(name);
  return s;
}

// Argument order follows the columns of Tables B.7-B.10.
FootSpec hmt_spec(double k_h, double k_t, double k_hm, double k_mt, double h_f, double l_ha, double l_hm, double l_mt,
                  double gamma_deg, std::string name) {
  FootSpec s;
  s.model = FootModel::hmt;
  s.parameters.resize(hmt::count);
  s.parameters << h_f * mm, l_ha * mm, l_hm * mm, l_mt * mm, gamma_deg * deg, k_h, k_hm, k_mt, k_t;
  s.name = std::move(name);
  return s;
}

FootSpec point_spec() {
  FootSpec s;
  s.model = FootModel::point;
  s.parameters.resize(0);
  s.name = "point foot";
  return s;
}

const std::vector<FootPreset>& presets() {
  static const std::vector<FootPreset> all = {
      {"P2-shoes-left-HMT", "seed 001 Table B.9 (P2, left, with shoes); best foot of section 9.2.3",
       hmt_spec(1e-8, 1e-8, 5.4e-2, 1.0e-1, 106.5, 76.5, 248.6, 112.4, 44.0, "P2 shoes left (HMT)")},
      {"P1-barefoot-left-HM", "seed 001 Table 4.2 (P1, left, barefoot); the chapter-8 experiments",
       hm_spec(1e-8, 1e-8, 5.2e-2, 88.5, 52.3, 226.6, "P1 barefoot left (HM)")},
      {"P1-shoes-left-HMT", "seed 001 Table B.9 (P1, left, with shoes)",
       hmt_spec(1e-8, 1e-8, 9.9e-2, 1.8e-2, 102.7, 94.8, 282.6, 58.9, 32.2, "P1 shoes left (HMT)")},
      {"point", "seed 001 Table D.1 (point feet)", point_spec()},
  };
  return all;
}

}  // namespace

std::span<const FootPreset> foot_presets() { return presets(); }

const FootPreset& foot_preset(std::string_view name) {
  for (const FootPreset& p : presets())
    if (p.name == name) return p;
  std::string known;
  for (const FootPreset& p : presets()) known += (known.empty() ? "" : ", ") + std::string(p.name);
  throw SpecError("preset", "unknown foot preset '" + std::string(name) + "'; known: " + known);
}

}  // namespace cyclopt::foot
