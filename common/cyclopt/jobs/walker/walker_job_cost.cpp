#include "cyclopt/jobs/walker/walker_job_cost.hpp"

#include <algorithm>
#include <cstdio>
#include <thread>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

// Seconds per SQP iteration and grid point (the 20-start multistarts of multistart_bench at
// P = 200: point feet 3.1 ms, rolling feet 5.1 ms per iteration; linear in P per job_cost_bench).
constexpr double kPointFootSecondsPerIterationAndPoint = 3.1e-3 / 200;
constexpr double kRollingFootSecondsPerIterationAndPoint = 5.1e-3 / 200;
// Iterations of one solve from a perturbed starting gait (multistart_bench: 133 point, 550-715 rolling).
constexpr double kPointFootIterationsPerSolve = 140;
constexpr double kRollingFootIterationsPerSolve = 700;
// Continuation iterations per grid value of a sweep, over all its curves (speed_sweep_bench:
// the 21-speed sweeps beyond their multistarts).
constexpr double kPointFootIterationsPerSweepValue = 300;
constexpr double kRollingFootIterationsPerSweepValue = 650;
// ... and of a single continuation curve (correctors warm-started from the QP predictor).
constexpr double kIterationsPerContinuationValue = 60;
// Memory of one solve: a base plus bytes per grid point (job_cost_bench peak RSS: point feet
// +8.4 / +47.7 MiB, P2 shoes +11.7 / +75.0 MiB at P = 200 / 2000, i.e. 22-35 kB per point; with a
// margin for the QP's working set at larger P).
constexpr double kBaseBytesPerSolve = 16.0 * (1 << 20);
constexpr double kBytesPerSolveAndPoint = 40e3;

int points_field_default() { return walker::WalkingConstants{}.points; }

}  // namespace

JobCost walker_job_cost(const WalkerJob& job, const std::string& task, int grid_values, int seed_speeds) {
  const bool point_foot = job.foot.model == foot::FootModel::point;
  const double p = job.constants.points;
  const double per_iteration =
      p * (point_foot ? kPointFootSecondsPerIterationAndPoint : kRollingFootSecondsPerIterationAndPoint);
  const double per_solve = std::min<double>(job.solver.max_iterations,
                                            point_foot ? kPointFootIterationsPerSolve : kRollingFootIterationsPerSolve);
  const int threads = std::max(1u, std::thread::hardware_concurrency());
  const double solve_bytes = kBaseBytesPerSolve + kBytesPerSolveAndPoint * p;

  double solves = 0.0, extra_iterations = 0.0;
  int concurrent = 1;
  std::string field = "points";
  if (task == "evaluate") {
    solves = 1.0 / per_solve;  // one evaluation
  } else if (task == "optimise") {
    solves = 1.0;
  } else if (task == "multistart") {
    solves = job.starts;
    concurrent = std::min(threads, job.starts);
    if (job.starts / 20.0 > p / points_field_default()) field = "multistart.starts";
  } else if (task == "sweep") {
    solves = static_cast<double>(seed_speeds) * job.starts;
    concurrent = std::min(threads, job.starts);
    extra_iterations = grid_values * (point_foot ? kPointFootIterationsPerSweepValue : kRollingFootIterationsPerSweepValue);
    if (grid_values / 21.0 > p / points_field_default()) field = "speeds";
  } else {  // continuation
    solves = 1.0;
    extra_iterations = grid_values * kIterationsPerContinuationValue;
    if (grid_values / 21.0 > p / points_field_default()) field = task == "continuation" ? "continuation.values" : "speeds";
  }
  const double iterations = solves * per_solve + extra_iterations;
  JobCost c;
  c.seconds = solves * per_solve * per_iteration / concurrent + extra_iterations * per_iteration;
  c.memory_bytes = concurrent * solve_bytes;
  c.field = field;
  char buf[256];
  std::snprintf(buf, sizeof buf, "%.0f iterations of %.3g s at P = %.0f%s, %d solve%s at a time of %s each", iterations,
                per_iteration, p, point_foot ? " (point feet)" : "", concurrent, concurrent == 1 ? "" : "s",
                memory_text(solve_bytes).c_str());
  c.breakdown = buf;
  return c;
}

}  // namespace cyclopt::jobs
