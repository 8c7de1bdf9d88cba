#pragma once
// The fields of the kinds that run several speed sweeps with the same options (foot_comparison,
// foot_design): the walker fields (walker_job_spec.hpp) and
//
//   "continuation": {"seed_speeds": "0.3:1:2.3", "min_trust_region": 0.002, "corrector_max_iterations": 300,
//                    "coarse_points": 100, "runner_ups": 0, "closure_passes": 8}
//
// the sweeps' multistart speeds (default 0.3, 1.3, 2.3), Delta_min (Table 7.1), the corrector's
// MaxIter at each continuation point (studies::SpeedSweepOptions::corrector_max_iterations) and the
// grid of the coarse-to-fine multistarts (SpeedSweepOptions::coarse_points, 0: off) and the further
// optima of each seed-speed multistart continued while best (SpeedSweepOptions::runner_ups, 0: the
// seed's workflow) and the passes at most of the envelope's closure (EnvelopeClosureOptions, 0: off).
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/studies/speed_sweep.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace cyclopt::jobs {

struct SweepFields {
  std::vector<double> seed_speeds{0.3, 1.3, 2.3};
  double min_trust_region = continuation::ContinuationOptions{}.min_trust_region;
  int corrector_max_iterations = studies::SpeedSweepOptions{}.corrector_max_iterations;
  int coarse_points = studies::SpeedSweepOptions{}.coarse_points;
  int runner_ups = studies::SpeedSweepOptions{}.runner_ups;
  int closure_passes = studies::EnvelopeClosureOptions{}.max_passes;  // 0: no closure
};

// Reads spec["continuation"] when present; throws SpecError naming the field.
SweepFields parse_sweep_fields(const nlohmann::json& spec);
// continuation.coarse_points of the "continuation" object c: 0 (off) or a grid of P points in
// [kMinGaitPoints, kMaxGaitPoints] like "points"; `fallback` when absent. Throws SpecError naming the field.
int parse_coarse_points(const nlohmann::json& c, int fallback);
// continuation.runner_ups of c: in [0, kMaxRunnerUps]; `fallback` when absent. Throws SpecError naming the field.
inline constexpr int kMaxRunnerUps = 10;
int parse_runner_ups(const nlohmann::json& c, int fallback);
// continuation.closure_passes of c: in [0, kMaxClosurePasses], 0 switching the closure off; `fallback` when absent.
inline constexpr int kMaxClosurePasses = 100;
int parse_closure_passes(const nlohmann::json& c, int fallback);
// The "continuation" block with every field (for the resolved spec, resolved_spec.hpp).
nlohmann::json sweep_fields_json(const SweepFields& fields);

// The options of every sweep: the walker job's speeds, solver, seed and scale, `starts` runs per
// seed speed.
studies::SpeedSweepOptions sweep_options(const WalkerJob& walker, const SweepFields& fields, int starts);

}  // namespace cyclopt::jobs
