#include "cyclopt/plot/sensitivity_figures.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

std::string change_text(const records::ActiveSetChangeRecord& c, double sign) {
  if (!std::isfinite(c.relative_change)) return "none predicted";
  return report_number(sign * 100.0 * c.relative_change, "%+.3g %%") + ": " + c.constraint + (c.enters ? " enters" : " leaves");
}

}  // namespace

std::vector<SensitivityParameter> sensitivity_parameters(const nlohmann::json& doc) {
  if (doc.value("task", "") != "sensitivity")
    throw std::invalid_argument("job " + std::to_string(doc.value("id", 0)) + " is a " + doc.value("task", std::string("?")) +
                                " job; the sensitivity chart needs a walker sensitivity job");
  std::vector<SensitivityParameter> out;
  std::vector<std::pair<int, records::SensitivityStepRecord>> steps;  // (parameter index, step)
  const nlohmann::json none = nlohmann::json::array();
  for (const nlohmann::json& s : doc.contains("solutions") ? doc["solutions"] : none) {
    const int curve = s.value("curve", 0), point = s.value("point", 0);
    if (curve == records::kSensitivitySummaryCurve) {
      if (static_cast<int>(out.size()) <= point) out.resize(static_cast<std::size_t>(point) + 1);
      out[static_cast<std::size_t>(point)].summary = s.at("values").get<records::SensitivitySummaryRecord>();
    } else if (curve >= records::sensitivity_continuation_curve(0)) {
      steps.emplace_back(curve - records::sensitivity_continuation_curve(0), s.at("values").get<records::SensitivityStepRecord>());
    }
  }
  for (auto& [k, step] : steps)
    if (k < static_cast<int>(out.size())) out[static_cast<std::size_t>(k)].steps.push_back(step);
  for (SensitivityParameter& p : out)
    std::sort(p.steps.begin(), p.steps.end(), [](const auto& a, const auto& b) { return a.relative_change < b.relative_change; });
  return out;
}

Figure sensitivity_figure(const std::vector<SensitivityParameter>& parameters) {
  LineChart chart;
  double range = 0.0;
  for (const SensitivityParameter& p : parameters) range = std::max(range, std::isfinite(p.summary.relative_range) ? p.summary.relative_range : 0.0);
  chart.axes = {"Change of the optimal f_mech per parameter: continuation (solid) and KKT tangent (dashed)",
                "relative change of the parameter (%)", "Δf_{mech} (-)", true};
  int index = 0;
  for (const SensitivityParameter& p : parameters) {
    if (p.steps.empty()) continue;
    const Color c = palette(index++);
    Series curve{p.summary.parameter, {}, {}, true, false, c};
    for (const records::SensitivityStepRecord& s : p.steps) {
      curve.x.push_back(100.0 * s.relative_change);
      curve.y.push_back(s.delta_objective);
    }
    chart.series.push_back(std::move(curve));
    if (std::isfinite(p.summary.derivative))
      chart.series.push_back({p.summary.parameter + " KKT tangent", {-100.0 * range, 100.0 * range},
                              {p.summary.predicted_decrease, p.summary.predicted_increase}, false, true, c});
  }
  if (chart.series.empty()) throw std::invalid_argument("sensitivity: no parameter has a continuation point to draw");
  return {"sensitivity", "Δf_{mech} over ±" + report_number(100.0 * range, "%g") +
                             " % of each parameter (seed 001 Fig. 10.1): continuation points, KKT tangent dashed",
          chart, RenderOptions{900, 600}};
}

ReportTable sensitivity_comparison_table(const std::vector<SensitivityParameter>& parameters) {
  ReportTable t;
  double range = 0.0;
  for (const SensitivityParameter& p : parameters) range = std::max(range, std::isfinite(p.summary.relative_range) ? p.summary.relative_range : 0.0);
  const std::string minus = report_number(-100.0 * range, "%g") + " %", plus = report_number(100.0 * range, "%+g") + " %";
  t.header = {"parameter", "value", "KKT df/dp", "relative p/f df/dp", "Δf predicted " + minus, "Δf predicted " + plus,
              "Δf continuation " + minus, "Δf continuation " + plus, "verdict"};
  for (const SensitivityParameter& p : parameters) {
    const records::SensitivitySummaryRecord& s = p.summary;
    // The continuation's Delta f at the range, or at the furthest value it reached (marked).
    auto reached = [&](double delta, double at, double want) {
      if (!std::isfinite(delta)) return std::string("-");
      std::string v = report_number(delta, "%+.4g");
      if (std::abs(at - want) > 1e-9) v += " (at " + report_number(100.0 * at, "%+.3g") + " %)";
      return v;
    };
    t.rows.push_back({s.parameter, report_number(s.value, "%.4g"), report_number(s.derivative, "%+.4g"),
                      report_number(s.relative, "%+.4f"), report_number(s.predicted_decrease, "%+.4g"),
                      report_number(s.predicted_increase, "%+.4g"),
                      reached(s.continuation_decrease, s.reached_decrease, -s.relative_range),
                      reached(s.continuation_increase, s.reached_increase, s.relative_range), s.verdict});
  }
  return t;
}

ReportTable kkt_sensitivity_table(const records::KktSensitivitiesRecord& k) {
  ReportTable t;
  t.header = {"parameter", "value", "df/dp", "relative p/f df/dp", "kink", "active set changes at (decrease)",
              "active set changes at (increase)"};
  for (const records::ParameterSensitivityRecord& p : k.parameters)
    t.rows.push_back({p.name, report_number(p.value, "%.4g"), report_number(p.derivative, "%+.4g"), report_number(p.relative, "%+.4f"),
                      p.kink ? "yes" : "no", change_text(p.decrease, -1.0), change_text(p.increase, 1.0)});
  return t;
}

std::string kkt_sensitivity_text(const records::KktSensitivitiesRecord& k) {
  if (k.unavailable) return "No KKT sensitivities: " + *k.unavailable + ".";
  return "Derivatives of the optimal objective f* = " + report_number(k.objective, "%.6f") +
         " with respect to each model parameter from the Lagrangian at the KKT point (envelope theorem, no re-solve; "
         "studies/kkt_sensitivity.hpp). Relative: the % change of f* per % change of p. The last two columns: the change "
         "of p at which the linearised optimum first changes its active set on that side (a constraint becomes active, "
         "or an active one's multiplier reaches 0); up to there df/dp predicts Delta f linearly. Kink 'yes': that change "
         "lies within 1e-4 % of p, so f* bends at p itself (its derivative is still df/dp, but a difference quotient "
         "over a step is off by O(step)). Multipliers: " + k.multipliers + ", |grad_z L| = " +
         report_number(k.lagrangian_gradient, "%.1e") + ", " + std::to_string(k.active_constraints) + " active constraints" +
         (k.unique_multipliers ? "" : " with dependent gradients (the multipliers are one set of several)") +
         (k.weakly_active.empty() ? "" : ", " + std::to_string(k.weakly_active.size()) + " weakly active (active with multiplier ~0)") +
         ".";
}

}  // namespace cyclopt::plot
