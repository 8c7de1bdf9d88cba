#pragma once
// The walker's job kinds (scene "walker", fields in walker_job_spec.hpp):
//   evaluate    the periodic gait at a start (given x or the automatic starting gait) - one point
//   optimise    an energy-optimal gait at one speed (section 5.4) - one point
//   multistart  N optimisations from random perturbations of the start, in parallel; one point per
//               distinct optimum, best first (the chapter-8.1 experiment as a job)
//   sweep       optimal gaits over a speed grid, each warm-started from the previous speed's
//               optimum (falling back to the automatic starting gait) - one point per speed
// Every stored point carries the gait scalars, the solver summary and the gait parameters x in
// `values`, and the trajectories on the grid.

#include "cyclopt/service/job_kind.hpp"

namespace cyclopt::service {

JobKind walker_evaluate_kind();
JobKind walker_optimise_kind();
JobKind walker_multistart_kind();
JobKind walker_sweep_kind();

}  // namespace cyclopt::service
