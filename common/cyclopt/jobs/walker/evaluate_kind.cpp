// Job kind "evaluate" (scene walker): the periodic gait of the hybrid zero dynamics (seed 001
// section 5.3) at one speed, from the gait parameters x of "start" or the automatic starting gait;
// the walker fields of walker_job_spec.hpp. One point: the gait and where it was evaluated.
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/jobs/walker/walker_kinds.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

void run_evaluate(const WalkerJob& job, JobContext& ctx) {
  ctx.announce(1);
  ctx.add_curve(0, "gait evaluation", "speed");
  if (ctx.already_stored_points().count({0, 0})) return;
  const double v = job.speeds[0];
  const walker::GaitEvaluator ev(job.model());
  const walker::GaitStart start = walker::gait_start(ev, v, job.start);
  WalkerPoint p = walker_point(ev.evaluate(start.x, job.gait_options(v)), start, {0, 0}, v);
  p.row.iterations = 1;
  ctx.count_iterations(1);
  ctx.store_point(p.stored());
}

}  // namespace

JobKind evaluate_kind() { return one_speed_kind("evaluate", false, run_evaluate); }

}  // namespace cyclopt::jobs
