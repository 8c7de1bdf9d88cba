#include "cyclopt/plot/walker_job_report.hpp"

#include "cyclopt/plot/gait_animation.hpp"
#include "cyclopt/plot/gait_stroboscope.hpp"
#include "cyclopt/plot/job_provenance.hpp"
#include "cyclopt/plot/point_diagnostics.hpp"
#include "cyclopt/plot/sensitivity_figures.hpp"
#include "cyclopt/plot/speed_charts.hpp"
#include "cyclopt/plot/step_figures.hpp"
#include "cyclopt/plot/walker_figures.hpp"

#include <cmath>
#include <cstdio>
#include <set>

namespace cyclopt::plot {
namespace {

ReportTable result_table(const WalkerJobResults& r) {
  ReportTable t;
  t.header = {"v target (m/s)", "status", "converged", "f_{mech} (-)", "f_{usq} (-)",
              "mean speed v (m/s)", "step length x_{H}^{−} − x_{H}^{+} (m)", "step period T (s)", "Floquet Λ", "stable",
              "impact loss (J)", "max inequality"};
  for (const GaitPoint& p : r.points) {
    const records::GaitRecord& g = p.gait;
    t.rows.push_back({report_number(p.speed, "%.3f"), p.status, p.converged ? "yes" : "NO", report_number(g.f_mech, "%.5f"),
                      report_number(g.f_usq, "%.5f"), report_number(g.mean_speed, "%.4f"), report_number(g.step_length, "%.4f"),
                      report_number(g.step_period, "%.4f"), report_number(g.floquet_multiplier, "%.4f"),
                      g.real ? (g.stable ? "yes" : "no") : "-", report_number(g.impact_energy_loss, "%.3f"),
                      report_number(g.max_inequality, "%.2e")});
    t.failed.push_back(!p.converged);
  }
  return t;
}

std::string gait_caption(const GaitPoint& p) {
  return "v = " + report_number(p.gait.mean_speed, "%.2f") + " m/s, step length " + report_number(p.gait.step_length, "%.3f") +
         " m, T = " + report_number(p.gait.step_period, "%.3f") + " s";
}

// The stroboscopes of the slowest, the chosen and the fastest converged gait (Fig. 9.2 a-c), each
// at the size it is shown, so that its letters are the other charts' size.
ReportSection stroboscope_section(const WalkerJobResults& r, const GaitPoint* chosen) {
  ReportSection s;
  s.heading = "Stroboscopes (seed 001 Fig. 9.2)";
  s.figure_grid = true;
  std::vector<const GaitPoint*> drawable, shown;
  for (const GaitPoint& p : r.points)
    if (p.converged && p.trajectory) drawable.push_back(&p);
  if (!drawable.empty()) {
    shown.push_back(drawable.front());
    if (chosen && chosen != drawable.front() && chosen != drawable.back()) shown.push_back(chosen);
    if (drawable.back() != drawable.front()) shown.push_back(drawable.back());
  }
  if (shown.empty()) {
    s.text = "No converged gait with a stored trajectory.";
    return s;
  }
  s.text = "One step of the optimal gait at the slowest, the chosen and the fastest converged speed: 7 poses at equal "
           "times from impact to impact, each where it is (x = 0: the stance ankle at the impact starting the step), "
           "later poses darker. Grey: torso; blue: leg A, the stance leg; orange: leg B, the swing leg; red dots: the "
           "rolling contact point C_{1}; green dashed: the path of the swing foot's lowest point C_{2}.";
  for (const GaitPoint* p : shown) {
    const Scene scene = gait_stroboscope(r, *p, {.legend = false});
    const Figure f{"stroboscope", gait_caption(*p) + ", poses " + report_number(1000 * p->gait.step_period / 6, "%.0f") +
                                      " ms apart",
                   scene, fitted_options(scene, 450, 280, kPageWidth)};
    s.figures.push_back(report_figure(f));
  }
  return s;
}

}  // namespace

Report walker_job_report(const nlohmann::json& doc, double speed) {
  const WalkerJobResults r = walker_job_results(doc);
  Report report;
  report.title = "cyclopt job " + std::to_string(r.id) + ": " + r.label;
  report.subtitle = "walker " + doc.value("task", std::string()) + ", state " + doc.value("state", std::string()) + ", " +
                    std::to_string(doc.value("points_stored", 0)) + " points stored" +
                    (doc.contains("points_converged") && doc["points_converged"].is_number()
                         ? " (" + std::to_string(doc["points_converged"].get<int>()) + " required points converged), "
                         : std::string(", ")) +
                    report_number(doc.value("run_seconds", nlohmann::json()), "%.1f") + " s of computation, " +
                    std::to_string(doc.value("attempts", 0)) + " attempt(s)";
  ReportSection results;
  results.heading = "Solved points (curve 0: the best per speed)";
  results.text = "One row per requested speed; f_{mech} (eq. 5.102) and f_{usq} (eq. 5.101) per weight and step length, "
                 "Floquet multiplier Λ (eq. 5.89), stable for |Λ| < 1 (eq. 5.90), max inequality of eq. 5.104 "
                 "(≤ 0 is feasible). A speed without a converged gait is marked red.";
  results.tables.push_back(result_table(r));
  report.sections = {provenance_section(doc), results, point_diagnostics_section(doc)};
  for (const GaitPoint& p : r.points) {
    if (!p.sensitivities) continue;
    ReportSection k;
    k.heading = "KKT sensitivities of the optimum at v = " + report_number(p.speed, "%.3g") + " m/s";
    k.text = kkt_sensitivity_text(*p.sensitivities);
    if (!p.sensitivities->unavailable) k.tables.push_back(kkt_sensitivity_table(*p.sensitivities));
    report.sections.push_back(k);
  }
  if (doc.value("task", std::string()) == "sensitivity") {
    const std::vector<SensitivityParameter> parameters = sensitivity_parameters(doc);
    ReportSection c;
    c.heading = "KKT sensitivity against the continuation (seed 001 section 10.1)";
    c.text = "Per parameter: the KKT derivative's linear prediction of Δf at the ends of the range beside the change "
             "the continuation from the optimum measured there (QPSQP, the same objective). 'agrees': both sides reached "
             "the range, the active set is predicted not to change within it, and the continuation's one-sided difference "
             "quotients at its first step bracket the KKT derivative. 'kink: ...' names what breaks the linear picture "
             "(the active set changes, as l_{MT} at 2 % in the seed's Fig. 10.1; the prediction is then only a tangent), "
             "'continuation stopped: ...' why a side did not reach the range (Δf then at the furthest value reached).";
    c.tables.push_back(sensitivity_comparison_table(parameters));
    try {
      const Figure f = sensitivity_figure(parameters);
      c.figures.push_back(report_figure(f));
    } catch (const std::invalid_argument& e) {
      c.text += std::string(" Not drawn: ") + e.what() + ".";
    }
    report.sections.push_back(c);
  }
  ReportSection figures;
  figures.heading = "Figures over speed";
  std::vector<std::string> not_drawn;
  std::set<double> speeds;  // converged ones: a chart over speed needs two
  for (const GaitPoint& p : r.points)
    if (p.converged) speeds.insert(p.speed);
  if (speeds.size() < 2) {
    figures.heading = "Figures";
    figures.text = "One converged speed: the charts over speed (cost of transport, torques, step length, Floquet "
                   "multiplier) need two or more; a sweep draws them.";
    try {
      figures.figures.push_back(report_figure(walker_figure("foot", {r}, speed)));
    } catch (const std::invalid_argument&) {  // point feet: no foot to draw
    }
  } else {
    try {
      const Figure curves{"solution_curves",
                          "All " + std::to_string(r.curves.size()) + " stored solution curves (numbered as `cyclopt "
                          "query` numbers them) and curve 0, the best per speed, as the wide pale envelope (seed 001 "
                          "Fig. 9.1)",
                          solution_curves_chart(r), {}};
      figures.figures.push_back(report_figure(curves));
    } catch (const std::invalid_argument& e) {
      not_drawn.push_back(std::string("solution curves: ") + e.what());
    }
    for (const Figure& f : walker_figures({r}, speed, &not_drawn))
      if (f.name != "stroboscope") figures.figures.push_back(report_figure(f));
  }
  for (const std::string& why : not_drawn) figures.text += (figures.text.empty() ? "Not drawn: " : "; ") + why;
  report.sections.push_back(figures);
  const GaitPoint* chosen = chosen_point(r, speed);
  ReportSection step;
  if (chosen) {
    step.heading = "Within one step at v = " + report_number(chosen->gait.mean_speed, "%.2f") + " m/s (seed 001 Fig. 9.5)";
    step.text = "The gait at the " + std::string(std::isfinite(speed) ? "chosen" : "middle converged") +
                " speed (`cyclopt report --speed V` chooses another) over its relative step time, from impact (0) to "
                "impact (1). " + gait_caption(*chosen) + ".";
    for (const Figure& f : within_step_figures(r, *chosen)) step.figures.push_back(report_figure(f));
  } else {
    step.heading = "Within one step";
    step.text = "No converged gait with a stored trajectory.";
  }
  report.sections.push_back(step);
  report.sections.push_back(stroboscope_section(r, chosen));
  ReportSection animations;
  animations.heading = "Gait animations";
  animations.figure_grid = true;
  animations.text = "Two steps of the gait at every converged speed in real time, looping (animated SVG); leg A blue, "
                    "leg B orange. The clock reads the time since the loop began; the bar below the ground fills over "
                    "the two steps, marked at the step period T.";
  for (const GaitPoint& p : r.points)
    if (p.converged && p.trajectory) {
      ReportFigure animation;  // SVG only: the PDF leaves animations out
      animation.caption = gait_caption(p);
      animation.svg = gait_animation_svg(r, p);
      animations.figures.push_back(std::move(animation));
    }
  if (animations.figures.empty()) animations.text = "No converged gait with a stored trajectory to animate.";
  report.sections.push_back(animations);
  return report;
}

}  // namespace cyclopt::plot
