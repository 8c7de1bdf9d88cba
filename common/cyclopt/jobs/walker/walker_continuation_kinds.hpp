#pragma once
// The walker's continuation job kinds (scene "walker", the fields of walker_job_spec.hpp plus an
// optional "continuation" object):
//   continuation  one solution curve over "speeds" (p_0 first, then the requested values; the
//                 mean speed) or, with "continuation": {"parameter": "l_HM", "values": "0.20:0.01:0.25"},
//                 over a model parameter at the first of "speeds" (seed 001, Algorithm 2)
//   sweep         the chapter-9 workflow (studies/speed_sweep.hpp) over "speeds": multistart
//                 ("multistart": starts, seed, scale) at the seed speeds, continuation of the best
//                 optima both ways and of every curve jumped to, best point per speed
//
//   "continuation": {"predictor": "qp" | "trivial" | "trivial_then_qp", "fixed_step": 0.2, "min_trust_region": 0.002,
//                    "max_trust_region": 0.1, "parameter": "speed", "values": ..., "seed_speeds": [0.3, 1.3, 2.3]}
//
// Storage: solution curve c of the continuation is curve_index c (sweep: c + 1, curve 0 holds the
// best point per speed once the sweep is done); points are numbered in the order solved along
// their curve and stored the moment they exist, each with its curve id, whether it is a requested
// value, the predictor's tries, steps and kappa (7.2), and the jumps in values.jump. The
// computation is deterministic, so a resumed job recomputes and stores only the missing points.
#include "cyclopt/service/job_kind.hpp"

namespace cyclopt::jobs {

service::JobKind walker_continuation_kind();
service::JobKind walker_sweep_kind();

}  // namespace cyclopt::jobs
