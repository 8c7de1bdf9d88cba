#include "cyclopt/foot/foot_spec.hpp"

#include "cyclopt/foot/convexity_constraints.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

namespace cyclopt::foot {
namespace {

void check_range(double x, const std::string& field, double lo, double hi, std::string_view unit) {
  if (!std::isfinite(x) || x < lo || x > hi) {
    std::ostringstream os;
    os << "must be in " << range_text(lo, hi, unit) << ", got " << x;
    throw SpecError(field, os.str());
  }
}

}  // namespace

void validate(const FootSpec& spec, const std::string& path) {
  const auto layout = parameter_layout(spec.model);
  if (spec.parameters.size() != static_cast<Eigen::Index>(layout.size()))
    throw SpecError(path, "model " + std::string(to_string(spec.model)) + " takes " + std::to_string(layout.size()) +
                              " parameters, got " + std::to_string(spec.parameters.size()));
  for (std::size_t i = 0; i < layout.size(); ++i)
    check_range(spec.parameters[static_cast<Eigen::Index>(i)], path + "." + std::string(layout[i].name),
                layout[i].min, layout[i].max, layout[i].unit);
  if (spec.model != FootModel::point) {
    // l_HA and l_HM sit at the same indices in both layouts (eq. 3.21 / 3.24: l_HM - l_HA >= 0).
    const double l_ha = spec.parameters[hm::l_HA], l_hm = spec.parameters[hm::l_HM];
    if (l_ha > l_hm) {
      std::ostringstream os;
      os << "must not exceed l_HM = " << l_hm << " m (the ankle projects onto the sole, eq. 3.21/3.24), got " << l_ha;
      throw SpecError(path + ".l_HA", os.str());
    }
  }
  if (spec.model == FootModel::hmt && toe_convexity_margin(spec.parameters) < 0.0) {
    std::ostringstream os;
    os << "toe segment (l_MT = " << spec.parameters[hmt::l_MT] << " m, gamma_F = " << spec.parameters[hmt::gamma_F]
       << " rad) lifts the toe tip so high that the polygon A-H-M-T is not convex at the ankle; need "
          "(l_HM - l_HA + l_MT cos gamma_F) h_F >= (l_MT sin gamma_F - h_F) l_HA";
    throw SpecError(path + ".gamma_F", os.str());
  }
  if (spec.periodic_terms < 0 || spec.periodic_terms > kMaxPeriodicTerms)
    throw SpecError(path + ".periodic_terms",
                    "must be an integer in [0, " + std::to_string(kMaxPeriodicTerms) + "], got " +
                        std::to_string(spec.periodic_terms));
  if (spec.density) check_range(*spec.density, path + ".density", kMinDensity, kMaxDensity, "kg/m^2");
  if (spec.theta_F0) check_range(*spec.theta_F0, path + ".theta_F0", -std::numbers::pi, std::numbers::pi, "rad");
}

}  // namespace cyclopt::foot
