// Job kind "multistart" (scene walker): `multistart.starts` optimisations at one speed from random
// perturbations (multistart.scale, rad) of "start" or the automatic starting gait, in parallel and
// reproducibly (multistart.seed; nlp/multistart.hpp), by the spec's solver: the chapter-8.1
// experiment as a job. One point per distinct optimum, best first (parameter: its rank), with the
// runs that reached it (records/multistart_record.hpp). The solves are journalled in the job's
// checkpoints (sweep_checkpoints.hpp), so a resumed job solves only the starts not finished.
#include "cyclopt/jobs/solver_progress.hpp"
#include "cyclopt/jobs/walker/sweep_checkpoints.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/jobs/walker/walker_kinds.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"
#include "cyclopt/nlp/multistart.hpp"
#include "cyclopt/records/multistart_record.hpp"
#include "cyclopt/walker/distant_start_solver.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"

#include <chrono>
#include <string>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

void run_multistart(const WalkerJob& job, JobContext& ctx) {
  ctx.add_curve(0, "distinct optima, best first", "rank");
  // The multistart is deterministic (seeded starts): a resumed job takes the solves an interrupted
  // attempt finished from its checkpoints, solves the rest, and stores the optima not stored yet
  // (store_point ignores stored keys).
  const double v = job.speeds[0];
  const walker::WalkerModel<double> model = job.model();
  const walker::GaitProblemOptions po = job.problem_at(v);
  const walker::GaitEvaluator ev(model);
  const Eigen::VectorXd centre = walker::gait_start(ev, v, job.start).x;
  const walker::GaitProblem shape(model, po);
  nlp::MultistartOptions mo;
  mo.num_starts = job.starts;
  mo.base_seed = job.seeds.front();
  mo.solver = walker::distant_start_solver(job.solver);
  mo.solver.on_iteration = stop_requests(ctx);
  mo.solver.should_stop = stop_predicate(ctx);
  const studies::SweepJournal journal = sweep_journal(ctx);
  studies::journal_multistart(mo, journal, 0);
  ProgressReport where{.parameter = v, .curve_id = 0, .points_total = -1,
                       .message = std::to_string(job.starts) + " starts at v = " + std::to_string(v) + " m/s",
                       .phase = "multistart", .phase_done = 0, .phase_total = job.starts};
  ctx.report_progress(where);
  const auto started = std::chrono::steady_clock::now();
  mo.on_progress = [&](int done, double best) {  // from the multistart's workers, one call at a time
    where.phase_done = done;
    where.best_objective = best;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    where.eta_seconds = seconds / done * (job.starts - done);  // runs taken from checkpoints make it optimistic
    ctx.report_progress(where);
  };
  const nlp::MultistartResult r = nlp::multistart(
      [&] { return std::make_unique<walker::GaitProblem>(model, po); },
      [&](std::mt19937_64& rng) { return shape.initial_point(walker::perturbed_gait(ev, centre, job.scale, rng)); }, mo);
  if (ctx.stop_reason() != StopReason::none) return;
  int total_iterations = 0;
  for (const nlp::SolverSummary& s : r.runs) total_iterations += s.iterations;
  ctx.count_iterations(total_iterations);
  ctx.announce(static_cast<int>(r.optima.size()));
  for (std::size_t k = 0; k < r.optima.size(); ++k) {
    const nlp::MultistartOptimum& o = r.optima[k];
    walker::GaitOptimum opt;
    opt.summary = r.runs[o.starts.front()];
    opt.z = o.x;
    opt.gait = shape.gait_at(o.x);
    opt.start = "multistart run " + std::to_string(o.starts.front());
    const records::MultistartOptimumRecord reached{
        .reached_by_starts = o.starts, .kkt_successes = r.successes, .starts = job.starts, .wall_seconds = r.wall_seconds};
    ctx.store_point(walker_point(opt, {0, static_cast<int>(k)}, static_cast<double>(k + 1)).stored(reached));
  }
}

}  // namespace

JobKind multistart_kind() { return one_speed_kind("multistart", true, run_multistart); }

}  // namespace cyclopt::jobs
