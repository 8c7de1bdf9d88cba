#pragma once
// The job kinds about feet (scene "walker"), one file each, which documents its spec:
//   foot_sweep       a foot's mass properties and rolling kinematics over a grid of one of its
//                    parameters (seed 001 ch. 3, appendix E)
//   foot_fit         HM and HMT feet fitted to gait-lab ankle tracks (section 4.2)
//   foot_comparison  one chapter-9 speed sweep per foot, the best foot per speed and each foot's
//                    saving against the reference (section 9.2)
//   foot_design      the foot-geometry optimisation per density (section 10.2)
// The comparison and the design sweep on the walker (walker/); a walker job's foot may name a fit
// a foot_fit job stored (stored_foot_fit.hpp).
#include "cyclopt/service/job_kind.hpp"

namespace cyclopt::jobs {

service::JobKind foot_sweep_kind();       // foot_sweep_kind.cpp
service::JobKind foot_fit_kind();         // foot_fit_kind.cpp
service::JobKind foot_comparison_kind();  // foot_comparison_kind.cpp
service::JobKind foot_design_kind();      // foot_design_kind.cpp

// The checkpoint each foot's work unit of a comparison leaves as its result, under the unit's
// prefix ("unit/foot-<k>/", service/unit_job_context.hpp): the foot's sweep summary as
// foot_sweep_to_json (walker/sweep_checkpoints.hpp) writes it.
inline constexpr const char* kSweptFootCheckpoint = "swept foot";

}  // namespace cyclopt::jobs
