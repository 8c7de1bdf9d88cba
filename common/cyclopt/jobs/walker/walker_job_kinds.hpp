#pragma once
// The walker's job kinds (scene "walker", fields in walker_job_spec.hpp):
//   evaluate    the periodic gait at a start (given x or the automatic starting gait) - one point
//   optimise    an energy-optimal gait at one speed (section 5.4) - one point
//   multistart  N optimisations from random perturbations of the start, in parallel; one point per
//               distinct optimum, best first (the chapter-8.1 experiment as a job)
// (continuation and the chapter-9 sweep: walker_continuation_kinds.hpp)
// Every stored point carries the gait scalars, the solver summary and the gait parameters x in
// `values`, and the trajectories on the grid.

#include "cyclopt/service/job_kind.hpp"

namespace cyclopt::jobs {

service::JobKind walker_evaluate_kind();
service::JobKind walker_optimise_kind();
service::JobKind walker_multistart_kind();

}  // namespace cyclopt::jobs
