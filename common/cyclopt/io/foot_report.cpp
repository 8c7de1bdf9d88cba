#include "cyclopt/io/foot_report.hpp"

#include "cyclopt/foot/convexity_constraints.hpp"
#include "cyclopt/foot/mass_properties.hpp"
#include "cyclopt/foot/rolling_kinematics.hpp"
#include "cyclopt/io/foot_spec_json.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace cyclopt::io {

using namespace foot;

namespace {

FootProfile<double> profile_of(const FootSpec& spec) {
  return make_profile(spec.model, spec.parameters, spec.periodic_terms);
}

// One sample of the rolling kinematics at foot angle theta (profile angle, before theta_F0).
nlohmann::json rolling_sample(const FootProfile<double>& prof, double theta) {
  const RollingContact<double> c = rolling_contact(prof, theta);
  const Vector2<double> ankle = ankle_position(c);
  const Vector2<double> contact = contact_point_from_ankle(c);
  return {{"theta", theta},
          {"ankle_x", ankle.x()},
          {"ankle_z", ankle.y()},
          {"contact_x_from_ankle", contact.x()},
          {"contact_z_from_ankle", contact.y()},
          {"curvature_radius", curvature_radius(prof, theta)}};
}

}  // namespace

nlohmann::json foot_report(const foot::FootSpec& spec, const FootReportOptions& options) {
  if (options.samples < 2) throw std::invalid_argument("foot report: samples must be >= 2, got " + std::to_string(options.samples));
  foot::validate(spec);
  const FootProfile<double> prof = profile_of(spec);
  nlohmann::json r;
  r["spec"] = to_json(spec);
  r["units"] = {{"length", "m"}, {"angle", "rad"}, {"mass", "kg"}, {"inertia", "kg m^2"}, {"density", "kg/m^2"}};
  r["admissible_theta"] = {prof.theta_min, prof.theta_max};
  nlohmann::json transitions = nlohmann::json::array();
  for (int i = 0; i < prof.transition_count; ++i)
    transitions.push_back({{"length", prof.transitions[i].length},
                           {"angle", prof.transitions[i].angle},
                           {"k", prof.transitions[i].k},
                           {"max_curvature_radius_estimate",  // eq. (3.16)
                            prof.transitions[i].length / 2 * (1 + prof.transitions[i].k * prof.transitions[i].k) /
                                prof.transitions[i].k}});
  r["transitions"] = transitions;
  if (spec.model == FootModel::hmt) r["toe_convexity_margin"] = toe_convexity_margin(spec.parameters);
  if (spec.density && spec.model != FootModel::point) {
    const FootMassProperties<double> mp = mass_properties(prof, *spec.density);
    r["mass_properties"] = {{"area", mp.area},       {"mass", mp.mass},
                            {"com_x", mp.com_x},     {"com_z", mp.com_z},
                            {"com_distance", mp.com_distance},
                            {"inertia_ankle", mp.inertia_ankle},
                            {"inertia_com", mp.inertia_com},
                            {"theta_F0", mp.theta_F0}};
    if (!spec.theta_F0) r["theta_F0"] = mp.theta_F0;
  }
  if (spec.theta_F0) r["theta_F0"] = *spec.theta_F0;
  nlohmann::json samples = nlohmann::json::array();
  for (int i = 0; i < options.samples; ++i)
    samples.push_back(rolling_sample(prof, prof.theta_min + (prof.theta_max - prof.theta_min) * i / (options.samples - 1)));
  r["rolling"] = samples;
  return r;
}

}  // namespace cyclopt::io
