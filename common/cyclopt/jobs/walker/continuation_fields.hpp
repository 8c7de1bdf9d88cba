#pragma once
// The "continuation" block of a walker job spec: one vocabulary for every kind that continues
// solutions (seed 001 Algorithm 2, defaults Table 7.1), read once into the study's options.
//
//   "continuation": {"predictor": "qp" | "trivial" | "trivial_then_qp", "predictor_hessian": "per_point" | "per_try",
//                    "fixed_step": 0.2, "min_trust_region": 0.002, "max_trust_region": 0.1,
//                    "parameter": "speed" | a model parameter, "values": "0.20:0.01:0.25",
//                    "seed_speeds": [0.3, 1.3, 2.3], "corrector_max_iterations": 300, "coarse_points": 100,
//                    "runner_ups": 0, "closure_passes": 8}
//
// Every kind accepts (and checks) every key and uses those that apply to it: the step control (predictor ..
// max_trust_region, continuation::ContinuationOptions) applies to all; "parameter" and "values"
// (a model parameter continued instead of the speed) to the continuation kind, which alone may
// continue anything but the speed; the rest to the kinds that run chapter-9 speed sweeps (sweep,
// foot_comparison, foot_design): their multistart speeds, the corrector's MaxIter at each
// continuation point (studies::SpeedSweepOptions::corrector_max_iterations), the coarse-to-fine
// multistarts' grid (coarse_points, 0: off), the further optima of each seed-speed multistart
// continued while best (runner_ups, 0: the seed's workflow) and the envelope closure's passes
// at most (closure_passes, 0: off).
#include "cyclopt/continuation/continuation_options.hpp"
#include "cyclopt/studies/speed_sweep.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace cyclopt::jobs {

inline constexpr int kMaxRunnerUps = 10;
inline constexpr int kMaxClosurePasses = 100;

// What the continuation kind continues: "speed" over the job's speeds, or a model parameter over
// the values in the block (their range is the parameter's, checked by the kind).
struct ContinuedParameter {
  std::string name = "speed";
  std::optional<nlohmann::json> values;  // "continuation.values" as given
};

// The block's step control into `options` (other members kept); the parameter continued, one of
// `parameters`. Throws SpecError naming the field ("continuation.fixed_step").
ContinuedParameter parse_curve_continuation(const nlohmann::json& spec, continuation::ContinuationOptions& options,
                                            const std::vector<std::string>& parameters);

// The whole block into the options of a speed sweep (other members kept): the step control into
// sweep.continuation and the sweep's own keys. Throws SpecError naming the field; a parameter
// other than the speed is refused (a sweep continues over the speed).
void parse_sweep_continuation(const nlohmann::json& spec, studies::SpeedSweepOptions& sweep);

// The block back with every key that applies (for a resolved spec, service/resolved_spec.hpp).
nlohmann::json curve_continuation_json(const continuation::ContinuationOptions& options, const std::string& parameter);
nlohmann::json sweep_continuation_json(const studies::SpeedSweepOptions& sweep);

}  // namespace cyclopt::jobs
