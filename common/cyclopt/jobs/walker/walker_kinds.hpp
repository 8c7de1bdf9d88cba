#pragma once
// The walker's job kinds (scene "walker", seed 001 ch. 5-10), one file each, which documents its
// spec beside the walker fields every one of them reads (walker_job_spec.hpp):
//   evaluate      the periodic gait at a start (given x or the automatic starting gait)
//   optimise      an energy-optimal gait at one speed (section 5.4), with its KKT sensitivities
//   multistart    N optimisations from random perturbations of the start; one point per distinct
//                 optimum, best first (the chapter-8.1 experiment as a job)
//   continuation  one solution curve over the speeds or a model parameter (Algorithm 2)
//   sweep         the chapter-9 workflow over the speeds: the best point per speed
//   sensitivity   an optimum's KKT sensitivities against the +-range continuation (section 10.1)
// Every stored point carries the gait scalars, the solver summary and the gait parameters x in
// its values and the trajectories on the grid (walker_points.hpp).
#include "cyclopt/service/job_kind.hpp"

namespace cyclopt::jobs {

service::JobKind evaluate_kind();      // evaluate_kind.cpp
service::JobKind optimise_kind();      // optimise_kind.cpp
service::JobKind multistart_kind();    // multistart_kind.cpp
service::JobKind continuation_kind();  // continuation_kind.cpp
service::JobKind sweep_kind();         // sweep_kind.cpp
service::JobKind sensitivity_kind();   // sensitivity_kind.cpp

}  // namespace cyclopt::jobs
