#include "cyclopt/plot/walker_job_report.hpp"

#include "cyclopt/plot/gait_animation.hpp"
#include "cyclopt/plot/sensitivity_figures.hpp"
#include "cyclopt/plot/walker_figures.hpp"

#include <cmath>
#include <cstdio>

namespace cyclopt::plot {
namespace {

ReportTable result_table(const WalkerJobResults& r) {
  ReportTable t;
  t.header = {"v target (m/s)", "status", "converged", "f_mech (-)", "f_usq (-)",
              "mean speed (m/s)", "step length (m)", "step period (s)", "Floquet Lambda", "stable",
              "impact loss (J)", "max inequality"};
  for (const GaitPoint& p : r.points) {
    const records::GaitRecord& g = p.gait;
    t.rows.push_back({report_number(p.speed, "%.3f"), p.status, p.converged ? "yes" : "no", report_number(g.f_mech, "%.5f"),
                      report_number(g.f_usq, "%.5f"), report_number(g.mean_speed, "%.4f"), report_number(g.step_length, "%.4f"),
                      report_number(g.step_period, "%.4f"), report_number(g.floquet_multiplier, "%.4f"),
                      g.real ? (g.stable ? "yes" : "no") : "-", report_number(g.impact_energy_loss, "%.3f"),
                      report_number(g.max_inequality, "%.2e")});
  }
  return t;
}

}  // namespace

Report walker_job_report(const nlohmann::json& doc) {
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
  ReportSection spec;
  spec.heading = "Job specification";
  spec.code = r.spec.dump(2);
  if (!doc.value("error", std::string()).empty())
    spec.text = (doc.value("state", std::string()) == "incomplete" ? "outcome: " : "error: ") + doc["error"].get<std::string>();
  ReportSection results;
  results.heading = "Solved points";
  results.text = "One row per requested speed; f_mech (eq. 5.102) and f_usq (eq. 5.101) per weight and step length, "
                 "Floquet multiplier Lambda (eq. 5.89), stable for |Lambda| < 1 (eq. 5.90), max inequality of eq. 5.104 "
                 "(<= 0 is feasible).";
  results.tables.push_back(result_table(r));
  ReportSection figures;
  figures.heading = "Figures";
  std::vector<std::string> not_drawn;
  for (const Figure& f : walker_figures({r}, std::nan(""), &not_drawn)) figures.figures.push_back({f.caption, svg_of(f)});
  for (const std::string& why : not_drawn) figures.text += (figures.text.empty() ? "Not drawn: " : "; ") + why;
  ReportSection animations;
  animations.heading = "Gait animations";
  animations.text = "Two steps of the gait at every converged speed in real time, looping (animated SVG); leg A blue, "
                    "leg B orange. The clock reads the time since the loop began; the bar below the ground fills over "
                    "the two steps, marked at the step period T.";
  for (const GaitPoint& p : r.points)
    if (p.converged && p.trajectory)
      animations.figures.push_back({"v = " + report_number(p.gait.mean_speed, "%.2f") + " m/s, step length " +
                                        report_number(p.gait.step_length, "%.3f") + " m, step period " +
                                        report_number(p.gait.step_period, "%.3f") + " s",
                                    gait_animation_svg(r, p)});
  if (animations.figures.empty()) animations.text = "No converged gait with a stored trajectory to animate.";
  report.sections = {spec, results};
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
    c.text = "Per parameter: the KKT derivative's linear prediction of Delta f at the ends of the range beside the change "
             "the continuation from the optimum measured there (QPSQP, the same objective). 'agrees': both sides reached "
             "the range, the active set is predicted not to change within it, and the continuation's one-sided difference "
             "quotients at its first step bracket the KKT derivative. 'kink: ...' names what breaks the linear picture "
             "(the active set changes, as l_MT at 2 % in the seed's Fig. 10.1; the prediction is then only a tangent), "
             "'continuation stopped: ...' why a side did not reach the range (Delta f then at the furthest value reached).";
    c.tables.push_back(sensitivity_comparison_table(parameters));
    try {
      const Figure f = sensitivity_figure(parameters);
      c.figures.push_back({f.caption, svg_of(f)});
    } catch (const std::invalid_argument& e) {
      c.text += std::string(" Not drawn: ") + e.what() + ".";
    }
    report.sections.push_back(c);
  }
  report.sections.push_back(figures);
  report.sections.push_back(animations);
  return report;
}

}  // namespace cyclopt::plot
