#pragma once
// Job kind "foot_comparison" (scene walker; issue 16 item 5, seed 001 section 9.2): one chapter-9
// speed sweep per foot, the best foot per speed and each foot's mean f_mech and saving against
// the reference feet (studies/foot_comparison.hpp).
//
//   {"scene": "walker", "task": "foot_comparison", "speeds": "0.3:0.1:2.3",
//    "feet": ["P1-shoes-left-HM-SG", "P2-shoes-left-HMT-SG", {"model": "HM", ...}],
//    "reference": "point", "multistart": {"starts": 20}}
//
// feet: preset names or foot specs (default: the 16 feet of section 9.2); reference: the foot
// savings are measured against (default "point", Table D.1), swept first; the other walker
// fields as for a sweep (speeds, points, bezier_degree, quadrature, objective, solver,
// multistart, continuation.seed_speeds / min_trust_region) apply to every foot; "foot", "start"
// and "free_parameters" are not fields of it.
//
// Stored curves: 0 the best foot per speed (its point, values.foot, values.saving); 1 the
// reference; 2 .. F+1 the feet in the given order, each the best point of its sweep per speed
// (values.found_by, or status "not found" with values.reason); F+2 one point per foot (parameter:
// its curve index) with values.foot, mean_f_mech, common_speeds, speeds_found, saving,
// best_fitted, sweep_seconds.
#include "cyclopt/service/job_kind.hpp"

namespace cyclopt::jobs {

service::JobKind foot_comparison_kind();

// The checkpoint each foot's work unit leaves as its result, under the unit's prefix
// ("unit/foot-<k>/", unit_job_context.hpp): the foot's sweep summary as foot_sweep_to_json
// (sweep_checkpoints.hpp) writes it.
inline constexpr const char* kSweptFootCheckpoint = "swept foot";

}  // namespace cyclopt::jobs
