#include "cyclopt/service/sweep_fields.hpp"

#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/service/value_range.hpp"

namespace cyclopt::service {

SweepFields parse_sweep_fields(const nlohmann::json& spec) {
  SweepFields f;
  if (!spec.contains("continuation")) return f;
  const nlohmann::json& c = object_value(spec["continuation"], "continuation");
  reject_unknown_keys(c, "continuation", {"seed_speeds", "min_trust_region", "corrector_max_iterations"});
  if (c.contains("seed_speeds"))
    f.seed_speeds = parse_value_range(c["seed_speeds"], "continuation.seed_speeds", kMinWalkingSpeed, kMaxWalkingSpeed);
  f.min_trust_region = optional_number(c, "continuation", "min_trust_region", 1e-9, 1e3).value_or(f.min_trust_region);
  f.corrector_max_iterations =
      optional_integer(c, "continuation", "corrector_max_iterations", 1, 100000).value_or(f.corrector_max_iterations);
  return f;
}

nlohmann::json sweep_fields_json(const SweepFields& fields) {
  return {{"seed_speeds", fields.seed_speeds},
          {"min_trust_region", fields.min_trust_region},
          {"corrector_max_iterations", fields.corrector_max_iterations}};
}

studies::SpeedSweepOptions sweep_options(const WalkerJob& walker, const SweepFields& fields, int starts) {
  studies::SpeedSweepOptions o;
  o.speeds = walker.speeds;
  o.starts = starts;
  o.seed = walker.seed;
  o.scale = walker.scale;
  o.seed_speeds = fields.seed_speeds;
  o.continuation.min_trust_region = fields.min_trust_region;
  o.corrector_max_iterations = fields.corrector_max_iterations;
  o.continuation.corrector = walker.solver;
  return o;
}

}  // namespace cyclopt::service
