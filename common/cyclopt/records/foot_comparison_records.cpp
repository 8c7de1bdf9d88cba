#include "cyclopt/records/foot_comparison_records.hpp"

#include <cmath>

namespace cyclopt::records {

namespace {

void put_finite(nlohmann::json& j, const char* key, double x) {
  if (std::isfinite(x)) j[key] = x;
}

}  // namespace

bool is_compared_foot(const nlohmann::json& values) { return values.is_object() && values.contains("foot_spec"); }

void to_json(nlohmann::json& j, const ComparedSpeedRecord& s) {
  j = nlohmann::json::object();
  if (!s.foot.empty()) j["foot"] = s.foot;
  if (s.found_by) j["found_by"] = *s.found_by;
  if (s.reason) j["reason"] = *s.reason;
  put_finite(j, "f_mech", s.f_mech);
  put_finite(j, "sweep_seconds", s.sweep_seconds);
  put_finite(j, "saving", s.saving);
  put_finite(j, "reference_f_mech", s.reference_f_mech);
  put_finite(j, "seed_spread", s.seed_spread);
}

void from_json(const nlohmann::json& j, ComparedSpeedRecord& s) {
  const std::string r = "values";
  s = ComparedSpeedRecord{};
  s.foot = optional_text(j, r, "foot").value_or("");
  s.found_by = optional_text(j, r, "found_by");
  s.reason = optional_text(j, r, "reason");
  s.f_mech = optional_number(j, r, "f_mech").value_or(kUnset);
  s.sweep_seconds = optional_number(j, r, "sweep_seconds").value_or(kUnset);
  s.saving = optional_number(j, r, "saving").value_or(kUnset);
  s.reference_f_mech = optional_number(j, r, "reference_f_mech").value_or(kUnset);
  s.seed_spread = optional_number(j, r, "seed_spread").value_or(kUnset);
}

void to_json(nlohmann::json& j, const ComparedFootRecord& f) {
  j = {{"foot", f.foot},
       {"reference", f.reference},
       {"mean_f_mech", finite_or_null(f.mean_f_mech)},
       {"saving", finite_or_null(f.saving)},
       {"common_speeds", f.common_speeds},
       {"speeds_found", f.speeds_found},
       {"speeds", f.speeds},
       {"best_fitted", f.best_fitted},
       {"sweep_seconds", f.sweep_seconds},
       {"curves", f.curves},
       {"foot_spec", f.foot_spec}};
  if (f.envelope_saving) j["envelope_saving"] = finite_or_null(*f.envelope_saving);
  if (f.envelope_common_speeds) j["envelope_common_speeds"] = *f.envelope_common_speeds;
  if (f.comparison_seconds) j["comparison_seconds"] = *f.comparison_seconds;
  if (!f.seed_savings.empty()) {
    j["seed_savings"] = nlohmann::json::array();
    for (double s : f.seed_savings) j["seed_savings"].push_back(finite_or_null(s));
  }
  if (f.rank) j["rank"] = *f.rank;
  if (f.order_held) j["order_held"] = *f.order_held;
}

void from_json(const nlohmann::json& j, ComparedFootRecord& f) {
  const std::string r = "values";
  f = ComparedFootRecord{};
  f.foot = text(j, r, "foot");
  f.reference = boolean(j, r, "reference");
  f.mean_f_mech = number(j, r, "mean_f_mech");
  f.saving = number(j, r, "saving");
  f.common_speeds = integer(j, r, "common_speeds");
  f.speeds_found = integer(j, r, "speeds_found");
  f.speeds = integer(j, r, "speeds");
  f.best_fitted = boolean(j, r, "best_fitted");
  f.sweep_seconds = number(j, r, "sweep_seconds");
  f.curves = integer(j, r, "curves");
  f.foot_spec = member(j, r, "foot_spec");
  if (j.contains("envelope_saving")) f.envelope_saving = number(j, r, "envelope_saving");
  if (j.contains("envelope_common_speeds")) f.envelope_common_speeds = integer(j, r, "envelope_common_speeds");
  if (j.contains("comparison_seconds")) f.comparison_seconds = number(j, r, "comparison_seconds");
  if (j.contains("seed_savings")) f.seed_savings = numbers(j, r, "seed_savings");
  if (j.contains("rank")) f.rank = integer(j, r, "rank");
  if (j.contains("order_held")) f.order_held = boolean(j, r, "order_held");
}

}  // namespace cyclopt::records
