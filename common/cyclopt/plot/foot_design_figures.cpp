#include "cyclopt/plot/foot_design_figures.hpp"

#include "cyclopt/plot/foot_figures.hpp"
#include "cyclopt/plot/gait_stroboscope.hpp"
#include "cyclopt/plot/html_report.hpp"
#include "cyclopt/records/foot_comparison_records.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

std::string rho_text(double rho) {
  char b[48];
  std::snprintf(b, sizeof b, "ρ = %g kg/m^{2}", rho);
  return b;
}

// The start foot's model with the parameters of `designed` (the record's member `field`) at the
// density; mass properties follow (E.3-E.7).
foot::FootSpec designed_spec(const foot::FootSpec& start, const records::DesignedFoot& designed, double density,
                             const std::string& field, const std::string& name) {
  foot::FootSpec f = start;
  const auto layout = foot::parameter_layout(start.model);
  for (std::size_t i = 0; i < layout.size(); ++i) {
    const auto it = designed.parameters.find(std::string(layout[i].name));
    if (it == designed.parameters.end())
      throw records::RecordError("values." + field + ".parameters." + std::string(layout[i].name) + ": is missing");
    f.parameters[static_cast<Eigen::Index>(i)] = it->second;
  }
  f.density = density;
  f.theta_F0.reset();
  f.name = name;
  return f;
}

}  // namespace

FootDesignCurves foot_design_curves(const nlohmann::json& doc) {
  FootDesignCurves c;
  c.id = doc.value("id", std::int64_t{0});
  if (doc.value("task", "") != "foot_design" || !doc.contains("spec"))
    throw std::invalid_argument("job " + std::to_string(c.id) + " is a " + doc.value("task", std::string("?")) +
                                " job; the foot design figures need a foot_design job");
  c.spec = stored_spec(doc);
  c.walker = stored_walker(c.spec);
  if (!c.walker.setup.design_speed) throw records::RecordError("spec.design_speed: is missing");
  c.design_speed = *c.walker.setup.design_speed;
  c.start = c.walker.foot;
  c.start_foot.name = "start foot " + c.start.name;
  c.point_feet.name = "point feet";
  const nlohmann::json none = nlohmann::json::array();
  const nlohmann::json& solutions = doc.contains("solutions") ? doc["solutions"] : none;
  for (const nlohmann::json& s : solutions)
    if (s.value("curve", -1) == records::kDesignCurve) {
      DesignedDensity d;
      d.record = s.at("values").get<records::DesignedFootRecord>();
      d.sweep.name = rho_text(d.record.density) + " design";
      d.low_sweep.name = rho_text(d.record.density) + " low-speed design";
      if (d.record.admissible) {
        d.design = designed_spec(c.start, d.record.design, d.record.density, "design", d.sweep.name);
        d.low_design = designed_spec(c.start, d.record.low_speed_design, d.record.density, "low_speed_design", d.low_sweep.name);
      }
      c.densities.push_back(std::move(d));
    }
  if (c.densities.empty())
    throw std::invalid_argument("job " + std::to_string(c.id) + " has no density stored yet (is it running?)");
  std::map<int, SweptCurve*> curves{{records::kStartFootCurve, &c.start_foot}, {records::kPointFeetCurve, &c.point_feet}};
  for (std::size_t k = 0; k < c.densities.size(); ++k) {
    curves[records::high_design_curve(static_cast<int>(k))] = &c.densities[k].sweep;
    curves[records::low_design_curve(static_cast<int>(k))] = &c.densities[k].low_sweep;
  }
  for (const nlohmann::json& s : solutions) {
    const auto it = curves.find(s.value("curve", -1));
    if (it == curves.end() || !s.at("parameter").is_number()) continue;
    const double f_mech = s["values"].get<records::ComparedSpeedRecord>().f_mech;
    if (!std::isfinite(f_mech)) continue;
    it->second->speed.push_back(s["parameter"].get<double>());
    it->second->f_mech.push_back(f_mech);
  }
  for (std::size_t k = 0; k < c.densities.size(); ++k) {
    const DesignedDensity& d = c.densities[k];
    if (d.record.admissible &&
        (c.best < 0 || d.answer_saving_vs_start() > c.densities[static_cast<std::size_t>(c.best)].answer_saving_vs_start()))
      c.best = static_cast<int>(k);
  }
  if (c.best >= 0)
    c.best_gaits = gait_points(doc, c.densities[static_cast<std::size_t>(c.best)].low_is_answer()
                                        ? records::low_design_curve(c.best)
                                        : records::high_design_curve(c.best));
  return c;
}

LineChart foot_design_cost_chart(const FootDesignCurves& c) {
  LineChart chart;
  chart.axes = {"f_{mech} of the designed feet, the start foot and point feet (seed 001 Fig. 10.7)", "mean speed v (m/s)",
                "mechanical cost of transport f_{mech} (eq. 5.102) (-)", true};
  if (!c.start_foot.speed.empty())
    chart.series.push_back({c.start_foot.name + " (its own masses)", c.start_foot.speed, c.start_foot.f_mech, false, true,
                            Color{0, 0, 0, 1}});
  if (!c.point_feet.speed.empty())
    chart.series.push_back({c.point_feet.name, c.point_feet.speed, c.point_feet.f_mech, false, true, Color{0.5, 0.5, 0.5, 1}});
  int colour = 0;
  for (const DesignedDensity& d : c.densities) {
    const Color color = palette(colour++);
    const auto add = [&](const SweptCurve& sweep, double vs_start, double vs_point, bool dashed) {
      if (sweep.speed.empty()) return;
      chart.series.push_back({sweep.name + " (saving " + report_number(100 * vs_start, "%.0f %%") + " vs start, " +
                                  report_number(100 * vs_point, "%.0f %%") + " vs point feet)",
                              sweep.speed, sweep.f_mech, true, dashed, color});
    };
    add(d.sweep, d.record.saving_vs_start, d.record.saving_vs_point, false);
    add(d.low_sweep, d.record.low_saving_vs_start, d.record.low_saving_vs_point, true);
  }
  if (chart.series.empty()) throw std::invalid_argument("foot design: no sweep has a point to draw");
  start_at_zero(chart);
  return chart;
}

Scene foot_design_outlines_scene(const FootDesignCurves& c) {
  Scene scene;
  scene.axes = {"Designed feet over the start foot, ankle at the dot (seed 001 Fig. 10.5/10.6)", "x from the ankle (m)",
                "z from the ankle (m)", true};
  scene.shapes.push_back({foot_outline(c.start), Color{0, 0, 0, 1}, 1.6, true, true, std::nullopt,
                          "start foot " + c.start.name});
  int colour = 0;
  for (const DesignedDensity& d : c.densities) {
    const Color color = palette(colour++);
    if (!d.record.admissible) continue;
    const bool best_density = &d - c.densities.data() == c.best;
    const auto add = [&](const foot::FootSpec& f, double m_F, bool low) {
      const bool best = best_density && low == d.low_is_answer();
      char legend[160];
      std::snprintf(legend, sizeof legend, "%s: m_F %.3f kg%s", f.name.c_str(), m_F, best ? " (best)" : "");
      scene.shapes.push_back({foot_outline(f), color, best ? 2.8 : 1.6, low, true, std::nullopt, legend});
    };
    add(d.design, d.record.design.m_F, false);
    add(d.low_design, d.record.low_speed_design.m_F, true);
  }
  scene.markers.push_back({0.0, 0.0, {0.1, 0.1, 0.1, 1}, 3, "ankle"});
  scene.legend_room = 300;
  return scene;
}

std::vector<Figure> foot_design_figures(const nlohmann::json& document, std::vector<std::string>* not_drawn) {
  return foot_design_figures(foot_design_curves(document), not_drawn);
}

std::vector<Figure> foot_design_figures(const FootDesignCurves& c, std::vector<std::string>* not_drawn) {
  auto skip = [&](const std::string& why) {
    if (not_drawn) not_drawn->push_back(why);
  };
  for (const DesignedDensity& d : c.densities)
    if (!d.record.admissible)
      skip(d.sweep.name + ": no admissible design (" + d.record.reason.value_or("no reason stored") + ")");
  std::vector<Figure> out;
  Scene outlines = foot_design_outlines_scene(c);
  const RenderOptions size = fitted_options(outlines, 800, 600, kPageWidth);
  out.push_back({"foot_design_outlines", "Designed feet per density over the start foot (seed 001 Fig. 10.5/10.6)",
                 std::move(outlines), size});
  try {
    out.push_back({"foot_design_cost", "f_{mech} over speed of each density's design (solid) and low-speed design "
                                       "(dashed), the start foot and point feet (seed 001 Fig. 10.7)",
                   foot_design_cost_chart(c), {}});
  } catch (const std::invalid_argument& e) {
    skip(std::string("foot-design-cost: ") + e.what());
  }
  if (c.best < 0) {
    skip("foot-design-gait: no density has an admissible design");
    return out;
  }
  // The best answer's gait at the design speed, from its fixed-foot sweep (Fig. 10.4).
  const DesignedDensity& best = c.densities[static_cast<std::size_t>(c.best)];
  WalkerJobResults r;
  r.id = c.id;
  r.label = best.answer_sweep().name;
  r.spec = c.spec;
  r.walker = c.walker;
  r.walker.foot = best.answer();
  r.points = c.best_gaits;
  const GaitPoint* p = point_near(r, c.design_speed);
  if (!p) {
    skip("foot-design-gait: the " + r.label + "'s sweep has no converged gait with a trajectory");
    return out;
  }
  Scene strobe = gait_stroboscope(r, *p);
  const RenderOptions strobe_size = fitted_options(strobe, 1000, 600, kPageWidth);
  char caption[160];
  std::snprintf(caption, sizeof caption, "Gait of the best design (%s) at %.2f m/s (seed 001 Fig. 10.4)", r.label.c_str(),
                p->speed);
  out.push_back({"foot_design_gait", caption, std::move(strobe), strobe_size});
  return out;
}

}  // namespace cyclopt::plot
