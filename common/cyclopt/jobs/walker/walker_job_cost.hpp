#pragma once
// The cost model of the walker job kinds (job_cost.hpp): solver iterations x seconds per
// iteration, which grows linearly with the grid size P (every iteration evaluates the gait and its
// Jacobian on P grid points, eq. 5.93, and solves a QP with 10 P + 3 inequalities, eq. 5.104),
// and memory per concurrent solve, linear in P (the dense 10 P x n constraint Jacobians of the
// problem and the SQP's QP). Calibrated with build/bench/job_cost_bench (bench/results/
// service_integration.txt) and the iteration counts of bench/results/multistart_bench.txt and
// speed_sweep_bench.txt.

#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/service/job_cost.hpp"

#include <string>

namespace cyclopt::jobs {

// task: evaluate | optimise | multistart | continuation | sweep; `grid_values`: the number of
// continuation or sweep values (ignored otherwise); `seed_speeds`: multistarts of a sweep.
service::JobCost walker_job_cost(const WalkerJob& job, const std::string& task, int grid_values, int seed_speeds);

}  // namespace cyclopt::jobs
