#include "cyclopt/plot/foot_design_report.hpp"

#include "cyclopt/foot/foot_parameters.hpp"
#include "cyclopt/plot/foot_design_figures.hpp"
#include "cyclopt/plot/job_provenance.hpp"
#include "cyclopt/plot/point_diagnostics.hpp"
#include "cyclopt/plot/sensitivity_figures.hpp"

#include <cmath>
#include <cstdio>

namespace cyclopt::plot {
namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : "; ") + s;
  return out.empty() ? "none" : out;
}

ReportTable outcome_table(const FootDesignCurves& c) {
  ReportTable t;
  t.header = {"ρ (kg/m^{2})", "outcome", "KKT starts", "optima admissible / stilt / wheel / no rolling / under-resolved",
              "f at design speed", "answer", "speeds reached", "mean f_mech", "saving vs start foot",
              "saving vs point feet", "wall (s)"};
  for (const DesignedDensity& d : c.densities) {
    const records::DesignedFootRecord& r = d.record;
    const bool low = d.low_is_answer();
    t.rows.push_back({report_number(r.density, "%g"),
                      r.admissible ? (&d - c.densities.data() == c.best ? "best design" : "design")
                                   : "no admissible design: " + r.reason.value_or("-"),
                      std::to_string(r.kkt_starts) + " / " + std::to_string(r.starts),
                      std::to_string(r.admissible_optima) + " / " + std::to_string(r.stilt_optima) + " / " +
                          std::to_string(r.wheel_optima) + " / " + std::to_string(r.no_rolling_optima) + " / " +
                          std::to_string(r.under_resolved_optima),
                      report_number(r.design_objective, "%.5f"), r.admissible ? r.answer : "-",
                      std::to_string(low ? r.low_speeds_reached : r.speeds_reached) + " / " + std::to_string(r.speeds),
                      report_number(low ? r.low_mean_f_mech : r.mean_f_mech, "%.5f"),
                      report_number(100 * d.answer_saving_vs_start(), "%.1f %%"),
                      report_number(100 * d.answer_saving_vs_point(), "%.1f %%"), report_number(r.seconds, "%.0f")});
  }
  return t;
}

// Both fixed-foot designs of every density with an admissible one: the foot (one column per
// parameter of the start foot's model), what follows it, and its sweep.
ReportTable design_table(const FootDesignCurves& c) {
  ReportTable t;
  t.header = {"ρ (kg/m^{2})", "foot (optimal at)"};
  const auto layout = foot::parameter_layout(c.start.model);
  for (const foot::ParameterInfo& p : layout) t.header.push_back(std::string(p.name) + " (" + std::string(p.unit) + ")");
  for (const char* h : {"m_{F} (kg)", "r_{F} (mm)", "J_{F} (kg m^{2})", "θ_{F,0} (rad)", "active bounds (10.1)", "speeds reached",
                        "mean f_mech", "saving vs start foot", "saving vs point feet"})
    t.header.push_back(h);
  for (const DesignedDensity& d : c.densities) {
    const records::DesignedFootRecord& r = d.record;
    if (!r.admissible) continue;
    for (const bool low : {false, true}) {
      const records::DesignedFoot& f = low ? r.low_speed_design : r.design;
      std::vector<std::string> row{report_number(r.density, "%g"),
                                   std::string(low ? "low-speed design (" : "design (") +
                                       report_number(low ? r.low_speed : c.design_speed, "%.2f") + " m/s)" +
                                       (low == d.low_is_answer() ? ", answer" : "")};
      for (const foot::ParameterInfo& p : layout) {
        const auto it = f.parameters.find(std::string(p.name));
        row.push_back(it == f.parameters.end() ? "-" : report_number(it->second, "%.4g"));
      }
      for (const std::string& v :
           {report_number(f.m_F, "%.3f"), report_number(1e3 * f.r_F, "%.1f"), report_number(f.J_F, "%.2e"),
            report_number(f.theta_F0, "%.3f"), low ? std::string("-") : joined(r.active_bounds),
            std::to_string(low ? r.low_speeds_reached : r.speeds_reached) + " / " + std::to_string(r.speeds),
            report_number(low ? r.low_mean_f_mech : r.mean_f_mech, "%.5f"),
            report_number(100 * (low ? r.low_saving_vs_start : r.saving_vs_start), "%.1f %%"),
            report_number(100 * (low ? r.low_saving_vs_point : r.saving_vs_point), "%.1f %%")})
        row.push_back(v);
      t.rows.push_back(std::move(row));
    }
  }
  return t;
}

}  // namespace

Report foot_design_report(const nlohmann::json& doc) {
  const FootDesignCurves c = foot_design_curves(doc);
  Report report;
  report.title = "cyclopt job " + std::to_string(c.id) + ": foot design from " + c.start.name;
  report.subtitle = "walker foot_design, state " + doc.value("state", std::string()) + ", " +
                    std::to_string(doc.value("points_stored", 0)) + " points stored, " +
                    report_number(doc.value("run_seconds", nlohmann::json()).is_number() ? doc["run_seconds"].get<double>() : std::nan(""),
                           "%.1f") +
                    " s of computation";
  ReportSection designs;
  designs.heading = "Designs per density";
  designs.text = "Per density: the design multistart at the design speed (foot and gait free, mass properties following "
                 "the geometry, appendix E), its optima by class (design_class.hpp), the best admissible optimum as the "
                 "design; the free-foot continuation to lower speeds, whose foot at the lowest speed it reached is the "
                 "low-speed design; and the fixed-foot sweeps of both: mean f_mech (eq. 5.102) over the speeds each "
                 "reached and the savings against the start foot (its own masses) and point feet over the speeds both "
                 "reach. The answer is the better of the two: the one reaching more speeds, of equal reach the lower "
                 "mean f_mech.";
  if (c.best >= 0) {
    const DesignedDensity& b = c.densities[static_cast<std::size_t>(c.best)];
    designs.text += " Best: the " + b.record.answer + " of ρ = " + report_number(b.record.density, "%g") +
                    " kg/m^{2}, saving " + report_number(100 * b.answer_saving_vs_start(), "%.1f") +
                    " % against the start foot and " + report_number(100 * b.answer_saving_vs_point(), "%.1f") +
                    " % against point feet.";
  } else {
    designs.text += " No density has an admissible design.";
  }
  designs.tables.push_back(outcome_table(c));
  designs.tables.push_back(design_table(c));
  ReportSection figures;
  figures.heading = "Figures";
  std::vector<std::string> not_drawn;
  for (const Figure& f : foot_design_figures(c, &not_drawn)) figures.figures.push_back(report_figure(f));
  for (const std::string& why : not_drawn) figures.text += (figures.text.empty() ? "Not drawn: " : "; ") + why;
  report.sections = {provenance_section(doc), designs, point_diagnostics_section(doc)};
  for (const DesignedDensity& d : c.densities) {
    if (!d.record.sensitivities) continue;
    ReportSection k;
    k.heading = "KKT sensitivities of the design at ρ = " + report_number(d.record.density, "%g") + " kg/m^{2}";
    k.text = kkt_sensitivity_text(*d.record.sensitivities) +
             " The foot parameters are free in the design, so only the fixed parameters appear.";
    if (!d.record.sensitivities->unavailable) k.tables.push_back(kkt_sensitivity_table(*d.record.sensitivities));
    report.sections.push_back(k);
  }
  report.sections.push_back(figures);
  return report;
}

}  // namespace cyclopt::plot
