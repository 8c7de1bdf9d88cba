#include "cyclopt/continuation/continuation_options.hpp"

#include <stdexcept>
#include <string>

namespace cyclopt::continuation {

const char* to_string(Predictor p) {
  switch (p) {
    case Predictor::qp: return "qp";
    case Predictor::trivial: return "trivial";
    case Predictor::trivial_then_qp: return "trivial_then_qp";
  }
  return "?";
}

namespace {

constexpr Predictor kPredictors[] = {Predictor::qp, Predictor::trivial, Predictor::trivial_then_qp};

}  // namespace

std::vector<std::string> predictor_names() {
  std::vector<std::string> names;
  for (Predictor p : kPredictors) names.emplace_back(to_string(p));
  return names;
}

Predictor parse_predictor(const std::string& text, const std::string& field) {
  for (Predictor p : kPredictors)
    if (text == to_string(p)) return p;
  std::string admissible;
  for (const std::string& name : predictor_names()) admissible += (admissible.empty() ? "\"" : ", \"") + name + "\"";
  throw std::invalid_argument(field + ": must be one of " + admissible + ", got \"" + text + "\"");
}

const char* predictor_hessian_name(bool reuse_predictor_hessian) { return reuse_predictor_hessian ? "per_point" : "per_try"; }

namespace {

void require(bool ok, const char* field, const char* range) {
  if (!ok) throw std::invalid_argument(std::string(field) + ": must be " + range);
}

}  // namespace

void validate(const ContinuationOptions& o) {
  require(o.eta > 0.0 && o.eta < 1.0, "eta", "in (0, 1)");
  require(o.tau > 0.0 && o.tau < 1.0, "tau", "in (0, 1)");
  require(o.initial_trust_region >= 0.0, "initial_trust_region", ">= 0");
  require(o.min_trust_region > 0.0, "min_trust_region", "> 0");
  require(o.max_trust_region >= 0.0, "max_trust_region", ">= 0");
  require(o.fixed_step >= 0.0, "fixed_step", ">= 0");
  require(o.active_tolerance >= 0.0, "active_tolerance", ">= 0");
  require(o.jump_slope_factor > 1.0, "jump_slope_factor", "> 1");
  require(o.jump_min_distance >= 0.0, "jump_min_distance", ">= 0");
  require(o.jump_first_distance >= o.jump_min_distance, "jump_first_distance", ">= jump_min_distance");
  nlp::validate(o.corrector);
}

}  // namespace cyclopt::continuation
