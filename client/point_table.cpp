#include "point_table.hpp"

#include "cyclopt/records/foot_comparison_records.hpp"
#include "cyclopt/records/foot_design_records.hpp"
#include "cyclopt/records/foot_fit_record.hpp"
#include "cyclopt/records/gait_records.hpp"
#include "cyclopt/records/sensitivity_records.hpp"

#include <cmath>
#include <cstdio>

namespace cyclopt::client {
namespace {

nlohmann::json member(const nlohmann::json& object, const char* key) {
  return object.is_object() && object.contains(key) ? object[key] : nlohmann::json();
}

nlohmann::ordered_json number(double x) { return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(); }

// A foot_fit point (service/foot_fit_kind.hpp): the fit's model, residuals and shape parameters.
std::optional<nlohmann::ordered_json> fit_summary(const nlohmann::json& row, const nlohmann::json& values) {
  records::FootFitRecord fit;
  try {
    fit = values.get<records::FootFitRecord>();
  } catch (const records::RecordError&) {
    return std::nullopt;
  }
  nlohmann::ordered_json s;
  s["curve"] = member(row, "curve");
  s["point"] = member(row, "point");
  s["model"] = fit.model;
  s["samples"] = fit.samples;
  s["rms_mm"] = number(1e3 * fit.rms);
  s["max_mm"] = number(1e3 * fit.max_residual);
  for (const records::FittedParameterRecord& p : fit.parameters)
    if (!p.fixed) s[p.name] = number(p.value);
  s["convex"] = fit.convex;
  s["status"] = member(row, "status");
  return s;
}

// A foot_design density (service/foot_design_kind.hpp): the classes of the multistart's optima
// (admissible/stilt/wheel/no rolling), the design's parameters and mass, the bounds (10.1) it
// touches, its fixed-foot sweep's mean f_mech and savings, and the speeds that sweep reached; the
// same for the low-speed design's sweep, and which of the two is the density's answer.
std::optional<nlohmann::ordered_json> design_summary(const nlohmann::json& row, const nlohmann::json& values) {
  records::DesignedFootRecord d;
  try {
    d = values.get<records::DesignedFootRecord>();
  } catch (const records::RecordError&) {
    return std::nullopt;
  }
  nlohmann::ordered_json s;
  s["rho_kg_m2"] = number(d.density);
  s["optima_a/s/w/n/u"] = std::to_string(d.admissible_optima) + "/" + std::to_string(d.stilt_optima) + "/" +
                          std::to_string(d.wheel_optima) + "/" + std::to_string(d.no_rolling_optima) + "/" +
                          std::to_string(d.under_resolved_optima);
  for (const auto& [name, value] : d.design.parameters) s[name] = number(value);
  s["m_F_kg"] = number(d.design.m_F);
  std::string bounds;
  for (const std::string& b : d.active_bounds) bounds += (bounds.empty() ? "" : ", ") + b.substr(0, b.find(' '));
  s["active_bounds"] = bounds;
  s["mean_f_mech"] = number(d.mean_f_mech);
  s["saving_vs_start_%"] = number(100 * d.saving_vs_start);
  s["saving_vs_point_%"] = number(100 * d.saving_vs_point);
  s["speeds"] = std::to_string(d.speeds_reached) + "/" + std::to_string(d.speeds);
  s["low_mean_f_mech"] = number(d.low_mean_f_mech);
  s["low_saving_vs_start_%"] = number(100 * d.low_saving_vs_start);
  s["low_saving_vs_point_%"] = number(100 * d.low_saving_vs_point);
  s["low_speeds"] = std::to_string(d.low_speeds_reached) + "/" + std::to_string(d.speeds);
  s["answer"] = d.answer;
  s["status"] = member(row, "status");
  return s;
}

// A sensitivity job's parameter (service/walker_sensitivity_kind.hpp): the KKT derivative, its
// linear prediction of Delta f at both ends of the range, the continuation's, and the verdict.
std::optional<nlohmann::ordered_json> sensitivity_summary(const nlohmann::json& values) {
  records::SensitivitySummaryRecord r;
  try {
    r = values.get<records::SensitivitySummaryRecord>();
  } catch (const records::RecordError&) {
    return std::nullopt;
  }
  nlohmann::ordered_json s;
  s["parameter"] = r.parameter;
  s["value"] = number(r.value);
  s["kkt_df_dp"] = number(r.derivative);
  s["relative"] = number(r.relative);
  s["predicted_minus"] = number(r.predicted_decrease);
  s["predicted_plus"] = number(r.predicted_increase);
  s["continuation_minus"] = number(r.continuation_decrease);
  s["continuation_plus"] = number(r.continuation_increase);
  s["verdict"] = r.verdict;
  return s;
}

// A foot_comparison's foot (jobs/foot/foot_comparison_kind.cpp, seed 001 section 9.2): mean f_mech
// (eq. 5.102) over the speeds it shares with the reference, its saving against the reference there,
// the speeds its sweep reached; the reference's row gives the best-foot envelope's saving instead;
// with several seeds the rank by saving and whether the order held with every seed.
std::optional<nlohmann::ordered_json> compared_foot_summary(const nlohmann::json& values) {
  records::ComparedFootRecord f;
  try {
    f = values.get<records::ComparedFootRecord>();
  } catch (const records::RecordError&) {
    return std::nullopt;
  }
  nlohmann::ordered_json s;
  s["foot"] = f.reference ? f.foot + " (reference)" : f.foot;
  s["mean_f_mech"] = number(f.mean_f_mech);
  s["saving_%"] = f.reference ? nlohmann::ordered_json() : number(100 * f.saving);
  s["over_speeds"] = f.common_speeds;
  s["speeds_found"] = std::to_string(f.speeds_found) + "/" + std::to_string(f.speeds);
  s["rank"] = f.rank ? nlohmann::ordered_json(*f.rank) : nlohmann::ordered_json();
  s["order_held"] = f.order_held ? nlohmann::ordered_json(*f.order_held ? "yes" : "no") : nlohmann::ordered_json();
  s["sweep_s"] = number(f.sweep_seconds);
  return s;
}

}  // namespace

std::optional<nlohmann::ordered_json> point_summary(const nlohmann::json& row) {
  const nlohmann::json values = member(row, "values");
  if (records::is_foot_fit(values)) return fit_summary(row, values);
  if (records::is_designed_foot(values)) return design_summary(row, values);
  if (records::is_sensitivity_summary(values)) return sensitivity_summary(values);
  if (records::is_compared_foot(values)) return compared_foot_summary(values);
  const nlohmann::json gait_json = member(values, "gait");
  if (!gait_json.is_object()) return std::nullopt;
  records::GaitRecord gait;
  try {
    gait = gait_json.get<records::GaitRecord>();
  } catch (const records::RecordError&) {
    return std::nullopt;  // not the contract's gait: shown column by column (row_table.hpp)
  }
  nlohmann::ordered_json s;
  s["curve"] = member(row, "curve");
  s["point"] = member(row, "point");
  s["speed_m_s"] = member(row, "parameter");
  s["f_mech"] = number(gait.f_mech);  // eq. 5.102
  if (gait.real && gait.objective != gait.f_mech) s["objective"] = number(gait.objective);  // f_usq jobs (eq. 5.101)
  s["step_length_m"] = number(gait.step_length);
  s["period_s"] = number(gait.step_period);
  // steps per minute: one step per period
  s["cadence_1_min"] = gait.step_period > 0 ? number(60.0 / gait.step_period) : nlohmann::ordered_json();
  s["floquet"] = number(gait.floquet_multiplier);  // eq. 5.89, stable for |Lambda| < 1
  s["impact_loss_J"] = number(gait.impact_energy_loss);
  s["status"] = member(row, "status");
  return s;
}

std::optional<std::string> comparison_envelope_line(const nlohmann::json& rows) {
  for (const nlohmann::json& row : rows) {
    const nlohmann::json values = member(row, "values");
    if (!records::is_compared_foot(values)) continue;
    records::ComparedFootRecord f;
    try {
      f = values.get<records::ComparedFootRecord>();
    } catch (const records::RecordError&) {
      continue;
    }
    if (!f.reference || !f.envelope_saving) continue;
    char line[200];
    std::snprintf(line, sizeof line, "the best foot at each speed saves %.1f %% mean f_mech against %s over %d speeds",
                  100 * *f.envelope_saving, f.foot.c_str(), f.envelope_common_speeds.value_or(0));
    return std::string(line);
  }
  return std::nullopt;
}

}  // namespace cyclopt::client
