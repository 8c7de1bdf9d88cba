#include "cyclopt/records/foot_fit_record.hpp"

namespace cyclopt::records {

namespace {

template <class T, class Read>
std::vector<T> list(const nlohmann::json& j, const std::string& record, const std::string& key, Read read) {
  const nlohmann::json& a = member(j, record, key);
  if (!a.is_array()) throw RecordError(record + "." + key + ": is not an array");
  std::vector<T> out;
  for (std::size_t i = 0; i < a.size(); ++i) out.push_back(read(a[i], record + "." + key + "[" + std::to_string(i) + "]"));
  return out;
}

}  // namespace

bool is_foot_fit(const nlohmann::json& values) {
  return values.is_object() && values.contains("model") && values.contains("convexity") && values.contains("foot");
}

void to_json(nlohmann::json& j, const FootFitRecord& f) {
  nlohmann::json parameters = nlohmann::json::array();
  for (const FittedParameterRecord& p : f.parameters)
    parameters.push_back({{"name", p.name},
                          {"unit", p.unit},
                          {"value", finite_or_null(p.value)},
                          {"lower", finite_or_null(p.lower)},
                          {"upper", finite_or_null(p.upper)},
                          {"standard_error", finite_or_null(p.standard_error)},
                          {"fixed", p.fixed},
                          {"at_bound", p.at_bound},
                          {"stride_spread", finite_or_null(p.stride_spread)},
                          {"boundary_spread", finite_or_null(p.boundary_spread)},
                          {"flag", p.flag}});
  nlohmann::json trials = nlohmann::json::array();
  for (const FittedTrialRecord& t : f.trials)
    trials.push_back({{"source", t.source},
                      {"samples", t.samples},
                      {"rms", finite_or_null(t.rms)},
                      {"max", finite_or_null(t.max)},
                      {"x_off", finite_or_null(t.x_off)}});
  nlohmann::json convexity = nlohmann::json::array();
  for (const ConvexityRowRecord& c : f.convexity)
    convexity.push_back({{"condition", c.condition}, {"value", finite_or_null(c.value)}});
  j = {{"model", f.model},
       {"converged", f.converged},
       {"message", f.message},
       {"iterations", f.iterations},
       {"seconds", finite_or_null(f.seconds)},
       {"samples", f.samples},
       {"unknowns", f.unknowns},
       {"rms", finite_or_null(f.rms)},
       {"max_residual", finite_or_null(f.max_residual)},
       {"noise_estimate", finite_or_null(f.noise_estimate)},
       {"parameters", parameters},
       {"trials", trials},
       {"convex", f.convex},
       {"convexity", convexity},
       {"foot", f.foot},
       {"spread_refits", f.spread_refits},
       {"spread_unconverged", f.spread_unconverged},
       {"boundary_tolerance", finite_or_null(f.boundary_tolerance)}};
}

void from_json(const nlohmann::json& j, FootFitRecord& f) {
  const std::string r = "values";
  f = FootFitRecord{};
  f.model = text(j, r, "model");
  f.converged = boolean(j, r, "converged");
  f.message = text(j, r, "message");
  f.iterations = integer(j, r, "iterations");
  f.seconds = number(j, r, "seconds");
  f.samples = integer(j, r, "samples");
  f.unknowns = integer(j, r, "unknowns");
  f.rms = number(j, r, "rms");
  f.max_residual = number(j, r, "max_residual");
  f.noise_estimate = number(j, r, "noise_estimate");
  f.parameters = list<FittedParameterRecord>(j, r, "parameters", [](const nlohmann::json& p, const std::string& at) {
    // The spreads and flag are absent in records stored before them.
    return FittedParameterRecord{text(p, at, "name"),
                                 text(p, at, "unit"),
                                 number(p, at, "value"),
                                 number(p, at, "lower"),
                                 number(p, at, "upper"),
                                 number(p, at, "standard_error"),
                                 boolean(p, at, "fixed"),
                                 boolean(p, at, "at_bound"),
                                 optional_number(p, at, "stride_spread").value_or(kUnset),
                                 optional_number(p, at, "boundary_spread").value_or(kUnset),
                                 optional_text(p, at, "flag").value_or("")};
  });
  f.trials = list<FittedTrialRecord>(j, r, "trials", [](const nlohmann::json& t, const std::string& at) {
    return FittedTrialRecord{text(t, at, "source"), integer(t, at, "samples"), number(t, at, "rms"), number(t, at, "max"),
                             number(t, at, "x_off")};
  });
  f.convex = boolean(j, r, "convex");
  f.convexity = list<ConvexityRowRecord>(j, r, "convexity", [](const nlohmann::json& c, const std::string& at) {
    return ConvexityRowRecord{text(c, at, "condition"), number(c, at, "value")};
  });
  f.foot = member(j, r, "foot");
  if (!f.foot.is_object()) throw RecordError("values.foot: is not a foot spec object");
  if (j.contains("spread_refits")) {  // records stored before the spreads have none
    f.spread_refits = integer(j, r, "spread_refits");
    f.spread_unconverged = integer(j, r, "spread_unconverged");
    f.boundary_tolerance = number(j, r, "boundary_tolerance");
  }
}

void to_json(nlohmann::json& j, const FootFitAnglesRecord& a) { j = {{"theta", a.theta}}; }

void from_json(const nlohmann::json& j, FootFitAnglesRecord& a) {
  const std::string r = "trajectory";
  a = FootFitAnglesRecord{};
  a.theta = list<std::vector<double>>(j, r, "theta", [](const nlohmann::json& trial, const std::string& at) {
    if (!trial.is_array()) throw RecordError(at + ": is not an array");
    std::vector<double> angles;
    for (std::size_t i = 0; i < trial.size(); ++i) {
      if (!trial[i].is_number()) throw RecordError(at + "[" + std::to_string(i) + "]: is not a number");
      angles.push_back(trial[i].get<double>());
    }
    return angles;
  });
}

}  // namespace cyclopt::records
