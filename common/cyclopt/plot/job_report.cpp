#include "cyclopt/plot/job_report.hpp"

#include "cyclopt/plot/foot_comparison_figures.hpp"
#include "cyclopt/plot/foot_design_report.hpp"
#include "cyclopt/plot/foot_fit_figures.hpp"
#include "cyclopt/plot/job_provenance.hpp"
#include "cyclopt/plot/point_diagnostics.hpp"
#include "cyclopt/plot/walker_job_report.hpp"

#include <functional>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

Report framed(const nlohmann::json& doc, const std::string& what) {
  Report r;
  r.title = "cyclopt job " + std::to_string(doc.value("id", 0)) + ": " + what;
  r.subtitle = doc.value("scene", std::string()) + " " + doc.value("task", std::string()) + ", state " +
               doc.value("state", std::string()) + ", " + std::to_string(doc.value("points_stored", 0)) + " points stored";
  r.sections.push_back(provenance_section(doc));
  return r;
}

// Figures drawn by `draw`, or the reason they could not be.
ReportSection figure_section(const std::function<std::vector<Figure>(std::vector<std::string>*)>& draw) {
  ReportSection s;
  s.heading = "Figures";
  std::vector<std::string> not_drawn;
  try {
    for (const Figure& f : draw(&not_drawn)) s.figures.push_back(report_figure(f));
  } catch (const std::invalid_argument& e) {
    not_drawn.push_back(e.what());
  }
  for (const std::string& why : not_drawn) s.text += (s.text.empty() ? "Not drawn: " : "; ") + why;
  return s;
}

}  // namespace

Report foot_comparison_report(const nlohmann::json& doc) {
  const FootComparisonCurves c = foot_comparison_curves(doc);
  Report r = framed(doc, "foot comparison of " + std::to_string(c.feet.size()) + " feet");
  ReportSection feet;
  feet.heading = "Feet and savings (seed 001 section 9.2)";
  feet.text = "Per foot: mean f_{mech} (eq. 5.102) of its best gaits against the reference over the speeds both reach; "
              "saving = 1 − mean f_{mech} / mean f_{mech} of the reference. The best-foot envelope saves " +
              report_number(100 * c.envelope_saving, "%.1f") + " % against the reference.";
  ReportTable t;
  t.header = {"foot", "role", "speeds reached", "saving vs reference (%)"};
  for (const ComparedFootCurve& f : c.feet)
    t.rows.push_back({f.name, f.reference ? "reference" : (f.best_fitted ? "best fitted foot" : "foot"),
                      std::to_string(f.speed.size()), f.reference ? "-" : report_number(100 * f.saving, "%.1f")});
  feet.tables.push_back(std::move(t));
  r.sections.push_back(feet);
  r.sections.push_back(point_diagnostics_section(doc));
  r.sections.push_back(figure_section([&doc](std::vector<std::string>*) { return foot_comparison_figures(doc); }));
  return r;
}

Report job_report(const nlohmann::json& doc, double speed) {
  const std::string scene = doc.value("scene", std::string()), task = doc.value("task", std::string());
  if (task == "foot_design") return foot_design_report(doc);
  if (task == "foot_comparison") return foot_comparison_report(doc);
  if (task == "foot_fit") {
    Report r = framed(doc, "foot fit");
    r.sections.push_back(point_diagnostics_section(doc));
    r.sections.push_back(figure_section([&doc](std::vector<std::string>* why) { return foot_fit_job_figures(doc, why); }));
    return r;
  }
  if (scene == "walker" && task != "foot_sweep") return walker_job_report(doc, speed);
  Report r = framed(doc, scene + " " + task);
  r.sections.push_back(point_diagnostics_section(doc));
  return r;
}

}  // namespace cyclopt::plot
