#pragma once
// The "design_bounds" field of a walker job: the foot dimension bounds of seed 001 eq. (10.1) for
// foot-geometry optimisation, every bound overridable,
//
//   "design_bounds": {"l_HM_max": 0.4, "h_F_max": 0.1, "toe_within_height": true,
//                     "k_HM_max": 0.5, "k_MT_max": 0.5}
//
// ({} takes the seed's values; HM feet have no toe bounds). Lengths in m, k in rad; each bound
// lies in the range of the parameter it limits (foot.schema.json). The start foot is moved onto
// the bounds in its free parameters (the seed's start P2 is taller than h_F,max); a bound that a
// fixed parameter of the start foot violates, or that leaves no convex start foot, is rejected
// naming the field and the admissible range.

#include "cyclopt/jobs/walker/walker_job_spec.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace cyclopt::jobs {

// Parses `v` (at JSON path `path`) into job.problem.design_bounds and moves job.foot onto them.
// Needs job.foot and job.problem.free_parameters parsed; throws SpecError.
void apply_design_bounds(const nlohmann::json& v, const std::string& path, WalkerJob& job);

}  // namespace cyclopt::jobs
