#include "cyclopt/jobs/walker/continuation_fields.hpp"

#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/service/value_range.hpp"

#include <algorithm>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

const std::vector<std::string> kKeys = {"predictor",   "predictor_hessian", "fixed_step",   "min_trust_region",
                                        "max_trust_region", "parameter",   "values",       "seed_speeds",
                                        "corrector_max_iterations", "coarse_points", "runner_ups", "closure_passes"};

// The block, or nullopt; throws SpecError when it is no object or holds an unknown key.
std::optional<nlohmann::json> block(const nlohmann::json& spec) {
  if (!spec.contains("continuation")) return std::nullopt;
  const nlohmann::json& c = object_value(spec["continuation"], "continuation");
  reject_unknown_keys(c, "continuation", kKeys);
  return c;
}

void parse_step_control(const nlohmann::json& c, continuation::ContinuationOptions& o) {
  if (c.contains("predictor"))
    o.predictor = continuation::parse_predictor(enum_value(c["predictor"], "continuation.predictor", continuation::predictor_names()));
  if (c.contains("predictor_hessian"))
    o.reuse_predictor_hessian = enum_value(c["predictor_hessian"], "continuation.predictor_hessian",
                                           {continuation::predictor_hessian_name(true),
                                            continuation::predictor_hessian_name(false)}) ==
                                continuation::predictor_hessian_name(true);
  o.fixed_step = optional_number(c, "continuation", "fixed_step", 0.0, 1e3).value_or(o.fixed_step);
  o.min_trust_region = optional_number(c, "continuation", "min_trust_region", 1e-9, 1e3).value_or(o.min_trust_region);
  o.max_trust_region = optional_number(c, "continuation", "max_trust_region", 0.0, 1e3).value_or(o.max_trust_region);
}

nlohmann::json step_control_json(const continuation::ContinuationOptions& o) {
  return {{"predictor", continuation::to_string(o.predictor)},
          {"predictor_hessian", continuation::predictor_hessian_name(o.reuse_predictor_hessian)},
          {"fixed_step", o.fixed_step},
          {"min_trust_region", o.min_trust_region},
          {"max_trust_region", o.max_trust_region}};
}

// The keys of a speed sweep into `sweep`.
void parse_sweep_keys(const nlohmann::json& c, studies::SpeedSweepOptions& sweep) {
  if (c.contains("seed_speeds"))
    sweep.seed_speeds = parse_value_range(c["seed_speeds"], "continuation.seed_speeds", kMinWalkingSpeed, kMaxWalkingSpeed);
  sweep.corrector_max_iterations =
      optional_integer(c, "continuation", "corrector_max_iterations", 1, 100000).value_or(sweep.corrector_max_iterations);
  const int coarse = optional_integer(c, "continuation", "coarse_points", 0, kMaxGaitPoints).value_or(sweep.coarse_points);
  if (coarse > 0 && coarse < kMinGaitPoints)
    throw SpecError("continuation.coarse_points", "must be 0 (off) or in " + range_text(kMinGaitPoints, kMaxGaitPoints) +
                                                      ", got " + std::to_string(coarse));
  sweep.coarse_points = coarse;
  sweep.runner_ups = optional_integer(c, "continuation", "runner_ups", 0, kMaxRunnerUps).value_or(sweep.runner_ups);
  if (const std::optional<int> passes = optional_integer(c, "continuation", "closure_passes", 0, kMaxClosurePasses)) {
    sweep.closure.enabled = *passes > 0;
    sweep.closure.max_passes = std::max(*passes, 1);
  }
}

}  // namespace

ContinuedParameter parse_curve_continuation(const nlohmann::json& spec, continuation::ContinuationOptions& options,
                                            const std::vector<std::string>& parameters) {
  ContinuedParameter p;
  const std::optional<nlohmann::json> c = block(spec);
  if (!c) return p;
  parse_step_control(*c, options);
  studies::SpeedSweepOptions unused;  // the sweeps' keys are checked, not used
  parse_sweep_keys(*c, unused);
  if (c->contains("parameter")) p.name = enum_value((*c)["parameter"], "continuation.parameter", parameters);
  if (c->contains("values")) p.values = (*c)["values"];
  return p;
}

void parse_sweep_continuation(const nlohmann::json& spec, studies::SpeedSweepOptions& sweep) {
  const std::optional<nlohmann::json> c = block(spec);
  if (!c) return;
  parse_step_control(*c, sweep.continuation);
  if (c->contains("parameter") && enum_value((*c)["parameter"], "continuation.parameter", {"speed"}) != "speed")
    throw SpecError("continuation.parameter", "a sweep continues over the speed");
  if (c->contains("values"))
    throw SpecError("continuation.values", "a sweep continues over its speeds; values of a model parameter need task continuation");
  parse_sweep_keys(*c, sweep);
}

nlohmann::json curve_continuation_json(const continuation::ContinuationOptions& options, const std::string& parameter) {
  nlohmann::json c = step_control_json(options);
  c["parameter"] = parameter;
  return c;
}

nlohmann::json sweep_continuation_json(const studies::SpeedSweepOptions& sweep) {
  nlohmann::json c = step_control_json(sweep.continuation);
  c["seed_speeds"] = sweep.seed_speeds;
  c["corrector_max_iterations"] = sweep.corrector_max_iterations;
  c["coarse_points"] = sweep.coarse_points;
  c["runner_ups"] = sweep.runner_ups;
  c["closure_passes"] = sweep.closure.enabled ? sweep.closure.max_passes : 0;
  return c;
}

}  // namespace cyclopt::jobs
