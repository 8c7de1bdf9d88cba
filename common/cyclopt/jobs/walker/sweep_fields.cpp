#include "cyclopt/jobs/walker/sweep_fields.hpp"

#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/service/value_range.hpp"

#include <algorithm>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

SweepFields parse_sweep_fields(const nlohmann::json& spec) {
  SweepFields f;
  if (!spec.contains("continuation")) return f;
  const nlohmann::json& c = object_value(spec["continuation"], "continuation");
  reject_unknown_keys(c, "continuation",
                      {"seed_speeds", "min_trust_region", "corrector_max_iterations", "coarse_points", "runner_ups",
                       "closure_passes"});
  if (c.contains("seed_speeds"))
    f.seed_speeds = parse_value_range(c["seed_speeds"], "continuation.seed_speeds", kMinWalkingSpeed, kMaxWalkingSpeed);
  f.min_trust_region = optional_number(c, "continuation", "min_trust_region", 1e-9, 1e3).value_or(f.min_trust_region);
  f.corrector_max_iterations =
      optional_integer(c, "continuation", "corrector_max_iterations", 1, 100000).value_or(f.corrector_max_iterations);
  f.coarse_points = parse_coarse_points(c, f.coarse_points);
  f.runner_ups = parse_runner_ups(c, f.runner_ups);
  f.closure_passes = parse_closure_passes(c, f.closure_passes);
  return f;
}

int parse_coarse_points(const nlohmann::json& c, int fallback) {
  const int points = optional_integer(c, "continuation", "coarse_points", 0, kMaxGaitPoints).value_or(fallback);
  if (points > 0 && points < kMinGaitPoints)
    throw SpecError("continuation.coarse_points", "must be 0 (off) or in " + range_text(kMinGaitPoints, kMaxGaitPoints) +
                                                      ", got " + std::to_string(points));
  return points;
}

int parse_runner_ups(const nlohmann::json& c, int fallback) {
  return optional_integer(c, "continuation", "runner_ups", 0, kMaxRunnerUps).value_or(fallback);
}

int parse_closure_passes(const nlohmann::json& c, int fallback) {
  return optional_integer(c, "continuation", "closure_passes", 0, kMaxClosurePasses).value_or(fallback);
}

nlohmann::json sweep_fields_json(const SweepFields& fields) {
  return {{"seed_speeds", fields.seed_speeds},
          {"min_trust_region", fields.min_trust_region},
          {"corrector_max_iterations", fields.corrector_max_iterations},
          {"coarse_points", fields.coarse_points},
          {"runner_ups", fields.runner_ups},
          {"closure_passes", fields.closure_passes}};
}

studies::SpeedSweepOptions sweep_options(const WalkerJob& walker, const SweepFields& fields, int starts) {
  studies::SpeedSweepOptions o;
  o.speeds = walker.speeds;
  o.starts = starts;
  o.seeds = walker.seeds;
  o.closure.enabled = fields.closure_passes > 0;
  o.closure.max_passes = std::max(fields.closure_passes, 1);
  o.scale = walker.scale;
  o.seed_speeds = fields.seed_speeds;
  o.continuation.min_trust_region = fields.min_trust_region;
  o.corrector_max_iterations = fields.corrector_max_iterations;
  o.coarse_points = fields.coarse_points;
  o.runner_ups = fields.runner_ups;
  o.continuation.corrector = walker.solver;
  return o;
}

}  // namespace cyclopt::jobs
