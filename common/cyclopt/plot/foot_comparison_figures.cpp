#include "cyclopt/plot/foot_comparison_figures.hpp"

#include "cyclopt/foot/fitted_feet.hpp"
#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/plot/foot_figures.hpp"
#include "cyclopt/records/foot_comparison_records.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

std::string percent(double saving) {
  if (!std::isfinite(saving)) return "saving ?";
  char s[48];
  std::snprintf(s, sizeof s, "saving %.0f %%", 100.0 * saving);
  return s;
}

}  // namespace

FootComparisonCurves foot_comparison_curves(const nlohmann::json& doc) {
  FootComparisonCurves c;
  c.id = doc.value("id", std::int64_t{0});
  if (doc.value("task", "") != "foot_comparison")
    throw std::invalid_argument("job " + std::to_string(c.id) + " is a " + doc.value("task", std::string("?")) +
                                " job; the foot comparison figures need a foot_comparison job");
  // The summary curve: one point per foot whose values hold the foot's spec; its parameter is the
  // foot's own curve index.
  std::map<int, std::size_t> foot_of_curve;
  for (const nlohmann::json& s : doc.value("solutions", nlohmann::json::array())) {
    if (!records::is_compared_foot(s.at("values"))) continue;
    const auto v = s["values"].get<records::ComparedFootRecord>();
    ComparedFootCurve f;
    f.name = v.foot;
    f.spec = io::foot_spec_from_json(v.foot_spec, "foot_spec");
    f.reference = v.reference;
    f.best_fitted = v.best_fitted;
    f.saving = v.saving;
    if (f.reference) c.envelope_saving = v.envelope_saving.value_or(std::nan(""));
    foot_of_curve[static_cast<int>(s.at("parameter").get<double>())] = c.feet.size();
    c.feet.push_back(std::move(f));
  }
  if (c.feet.empty())
    throw std::invalid_argument("job " + std::to_string(c.id) + " has no foot summary yet (is it finished?)");
  for (const nlohmann::json& s : doc.value("solutions", nlohmann::json::array())) {
    if (records::is_compared_foot(s.at("values"))) continue;
    const auto v = s["values"].get<records::ComparedSpeedRecord>();
    const double f_mech = v.f_mech;
    if (!std::isfinite(f_mech) || !s.at("parameter").is_number()) continue;
    const int curve = s.value("curve", -1);
    const double speed = s["parameter"].get<double>();
    if (curve == 0) {
      c.envelope_speed.push_back(speed);
      c.envelope_f_mech.push_back(f_mech);
      c.envelope_seed_spread.push_back(v.seed_spread);
    } else if (const auto it = foot_of_curve.find(curve); it != foot_of_curve.end()) {
      c.feet[it->second].speed.push_back(speed);
      c.feet[it->second].f_mech.push_back(f_mech);
    }
  }
  return c;
}

LineChart foot_comparison_chart(const FootComparisonCurves& c) {
  LineChart chart;
  chart.axes = {"f_{mech} of every foot and the best envelope (seed 001 Fig. 9.14/9.19a)", "mean speed v (m/s)",
                "mechanical cost of transport f_{mech} (eq. 5.102) (-)", true};
  int colour = 0;
  for (const ComparedFootCurve& f : c.feet) {
    if (f.speed.empty()) continue;
    Series s{f.name + (f.reference ? " (reference)" : " (" + percent(f.saving) + ")") + (f.best_fitted ? ", best" : ""),
             f.speed, f.f_mech, false, f.reference, std::nullopt};
    if (f.reference) {
      s.color = Color{0, 0, 0, 1};
    } else {  // the 11th foot on repeats the palette's colours, dashed (the seed compares 16 feet)
      s.dashed = colour >= kPaletteSize;
      s.color = palette(colour++);
    }
    chart.series.push_back(std::move(s));
  }
  if (!c.envelope_speed.empty()) {
    Series envelope{"best foot per speed (envelope, " + percent(c.envelope_saving) + ")", c.envelope_speed,
                    c.envelope_f_mech, true, false, Color{0.55, 0.0, 0.0, 1}};
    // Several seeds: shaded up to the worst seed's own search (f * (1 + spread)).
    Band band{c.envelope_speed, c.envelope_f_mech, {}, *envelope.color};
    bool spread = false;
    for (std::size_t i = 0; i < c.envelope_speed.size(); ++i) {
      const double w = i < c.envelope_seed_spread.size() ? c.envelope_seed_spread[i] : std::nan("");
      band.high.push_back(std::isfinite(w) ? c.envelope_f_mech[i] * (1.0 + w) : std::nan(""));
      spread = spread || std::isfinite(w);
    }
    if (spread) {
      envelope.label += "; shaded: spread over the seeds";
      chart.bands.push_back(std::move(band));
    }
    chart.series.push_back(std::move(envelope));
  }
  if (chart.series.empty()) throw std::invalid_argument("foot comparison: no foot has a point to draw");
  start_at_zero(chart);
  return chart;
}

Scene foot_outlines_scene(const FootComparisonCurves& c) {
  Scene scene;
  scene.axes = {"Outlines of the compared feet, ankle at each dot (seed 001 Fig. 9.8/9.13/9.16)",
                "x (m), one column per foot", "z (m)", true};
  constexpr int kColumns = 4;
  constexpr double kDx = 0.62, kDz = 0.30;  // wider and taller than the seed's largest fitted foot
  int k = 0;
  for (const ComparedFootCurve& f : c.feet) {
    if (f.spec.model == foot::FootModel::point) continue;
    const double ox = kDx * (k % kColumns), oz = -kDz * (k / kColumns);
    Shape s{foot_outline(f.spec), palette(k), f.best_fitted ? 2.8 : 1.6, false, true, std::nullopt,
            f.name + (f.best_fitted ? " (best)" : "")};
    for (auto& p : s.points) p = {p[0] + ox, p[1] + oz};
    scene.shapes.push_back(std::move(s));
    scene.markers.push_back({ox, oz, {0.1, 0.1, 0.1, 1}, 3, "ankle"});
    ++k;
  }
  if (scene.shapes.empty()) throw std::invalid_argument("foot comparison: only point feet, no outline to draw");
  scene.legend_room = 260;
  return scene;
}

std::vector<Figure> foot_comparison_figures(const nlohmann::json& document) {
  const FootComparisonCurves c = foot_comparison_curves(document);
  std::vector<Figure> out;
  out.push_back({"foot_comparison", "f_{mech} over speed of every compared foot with the best envelope (seed 001 Fig. 9.19a)",
                 foot_comparison_chart(c), {}});
  Scene outlines = foot_outlines_scene(c);
  const RenderOptions size = fitted_options(outlines, 760, 600, kPageWidth);
  out.push_back({"foot_outlines", "Outlines of the compared feet side by side (seed 001 Fig. 9.8/9.13/9.16)",
                 std::move(outlines), size});
  return out;
}

}  // namespace cyclopt::plot
