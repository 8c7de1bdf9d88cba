// Job kind "optimise" (scene walker): an energy-optimal gait at one speed (seed 001 section 5.4)
// from "start" or the automatic starting gait, by the spec's solver; the walker fields of
// walker_job_spec.hpp. One point: the optimum with its solve and, converged, its KKT
// sensitivities (studies/optimum_sensitivities.hpp).
#include "cyclopt/jobs/solver_progress.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/jobs/walker/walker_kinds.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"
#include "cyclopt/jobs/walker/walker_records.hpp"
#include "cyclopt/studies/optimum_sensitivities.hpp"
#include "cyclopt/walker/distant_start_solver.hpp"

#include <string>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

void run_optimise(const WalkerJob& job, JobContext& ctx) {
  ctx.announce(1);
  ctx.add_curve(0, "optimal gait", "speed");
  if (ctx.already_stored_points().count({0, 0})) return;
  const double v = job.speeds[0];
  nlp::SolverOptions solver = walker::distant_start_solver(job.solver);
  solver.on_iteration = solver_progress(
      ctx, {.parameter = v, .curve_id = 0, .points_done = 0, .points_total = 1, .message = "v = " + std::to_string(v) + " m/s"});
  solver.should_stop = stop_predicate(ctx);
  const walker::GaitOptimum opt = walker::optimise_gait(job.model(), job.problem_at(v), solver, job.start);
  if (ctx.stop_reason() != StopReason::none) return;
  ctx.report_progress({.parameter = v, .curve_id = 0, .points_done = 0, .points_total = 1,
                       .message = "KKT sensitivities at v = " + std::to_string(v) + " m/s"});
  const auto sensitivities = studies::optimum_sensitivities(job.model(), job.problem_at(v), opt, {}, stop_predicate(ctx));
  ctx.store_point(point_of(opt, {0, 0}, v, sensitivities_record(sensitivities)));
}

}  // namespace

JobKind optimise_kind() { return one_speed_kind("optimise", false, run_optimise); }

}  // namespace cyclopt::jobs
