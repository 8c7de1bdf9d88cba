#include "cyclopt/plot/foot_figures.hpp"

#include "cyclopt/foot/generating_polygon.hpp"
#include "cyclopt/foot/mass_properties.hpp"

#include <cmath>

namespace cyclopt::plot {
namespace {

foot::FootProfile<double> profile_of(const foot::FootSpec& s) {
  return foot::make_profile(s.model, s.parameters, s.periodic_terms);
}

std::string title_of(const foot::FootSpec& s) {
  return "foot " + std::string(foot::to_string(s.model)) + (s.name.empty() ? "" : ": " + s.name);
}

}  // namespace

std::vector<std::array<double, 2>> foot_outline(const foot::FootSpec& spec) {
  const foot::FootProfile<double> prof = profile_of(spec);
  // The quadrature panels of appendix E cluster where the outline bends: reuse them.
  const std::vector<double> br = foot::detail::panel_breakpoints(prof, 0.02);
  std::vector<std::array<double, 2>> pts;
  for (std::size_t j = 0; j + 1 < br.size(); ++j)
    for (int m = 0; m < 4; ++m) {
      const double a = br[j] + (br[j + 1] - br[j]) * m / 4.0;
      const foot::Vector2<double> c = foot::outline_point(foot::rolling_contact(prof, a), a);
      pts.push_back({c.x(), c.y()});
    }
  return pts;
}

Scene foot_shape_scene(const foot::FootSpec& spec) {
  Scene scene;
  scene.axes = {title_of(spec) + " (Fig. 3.5a)", "x from the ankle (m)", "z from the ankle (m)", true};
  Shape outline{foot_outline(spec), palette(0), 2.2, false, true, Color{0.12, 0.47, 0.71, 0.15}, "regularised outline"};
  double sole = 0;
  for (const auto& p : outline.points) sole = std::min(sole, p[1]);
  scene.shapes.push_back(outline);
  Shape polygon{{}, {0.3, 0.3, 0.3, 1}, 1.4, true, true, std::nullopt, "generating polygon"};
  for (const Eigen::Vector2d& v : foot::generating_polygon(spec.model, spec.parameters)) polygon.points.push_back({v.x(), v.y()});
  scene.shapes.push_back(polygon);
  scene.markers.push_back({0.0, 0.0, {0.1, 0.1, 0.1, 1}, 5, "ankle A"});
  if (spec.density) {
    const auto mp = foot::mass_properties(profile_of(spec), *spec.density);
    char label[96];
    std::snprintf(label, sizeof label, "centre of mass (m = %.3f kg at ρ = %.1f kg/m^{2})", mp.mass, *spec.density);
    scene.markers.push_back({mp.com_x, mp.com_z, palette(3), 5, label});
  }
  scene.ground_z = sole;
  return scene;
}

LineChart ankle_trajectory_chart(const foot::FootSpec& spec) {
  const foot::FootProfile<double> prof = profile_of(spec);
  // The polygon limit (k -> 0) of the same foot, eq. (3.2).
  foot::FootSpec sharp = spec;
  const int first_k = spec.model == foot::FootModel::hm ? int{foot::hm::k_H} : int{foot::hmt::k_H};
  for (int i = first_k; i < sharp.parameters.size(); ++i) sharp.parameters[i] = 1e-8;
  const foot::FootProfile<double> poly = profile_of(sharp);
  Series smooth{"regularised foot", {}, {}, false, false, std::nullopt};
  Series corner{"generating polygon (k -> 0)", {}, {}, false, true, std::nullopt};
  const int n = 600;
  for (int i = 0; i <= n; ++i) {
    const double th = prof.theta_min + (prof.theta_max - prof.theta_min) * i / n;
    const foot::RollingContact<double> c = foot::rolling_contact(prof, th);
    smooth.x.push_back(c.F);
    smooth.y.push_back(c.dF);
    const double tp = poly.theta_min + (poly.theta_max - poly.theta_min) * i / n;
    const foot::RollingContact<double> cp = foot::rolling_contact(poly, tp);
    corner.x.push_back(cp.F);
    corner.y.push_back(cp.dF);
  }
  LineChart chart;
  chart.axes = {title_of(spec) + ": ankle while rolling (Fig. 3.5b)", "ankle x_A (m)", "ankle height z_A (m)", true};
  chart.series = {smooth, corner};
  return chart;
}

}  // namespace cyclopt::plot
