#include "cyclopt/jobs/walker/walker_job_kinds.hpp"

#include "cyclopt/nlp/multistart.hpp"
#include "cyclopt/studies/optimum_sensitivities.hpp"
#include "cyclopt/jobs/walker/walker_job_cost.hpp"
#include "cyclopt/jobs/walker/walker_job_json.hpp"
#include "cyclopt/jobs/solver_progress.hpp"
#include "cyclopt/jobs/walker/sweep_checkpoints.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"
#include "cyclopt/jobs/walker/walker_records.hpp"
#include "cyclopt/walker/distant_start_solver.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"

#include <chrono>
#include <cmath>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

using walker::GaitOptimum;

walker::GaitProblemOptions problem_at(const WalkerJob& job, double speed) {
  walker::GaitProblemOptions o = job.problem;
  o.speed = speed;
  return o;
}

void run_evaluate(const WalkerJob& job, JobContext& ctx) {
  ctx.announce(1);
  ctx.add_curve(0, "gait evaluation", "speed");
  if (ctx.already_stored_points().count({0, 0})) return;
  const double v = job.speeds[0];
  const walker::GaitEvaluator ev(job.model());
  const walker::GaitStart start = walker::gait_start(ev, v, job.start);
  walker::GaitOptions go;
  go.objective = job.problem.objective;
  go.speed = v;
  go.quadrature = job.problem.quadrature;
  go.positive_power_band = job.problem.positive_power_band;
  storage::SolutionPoint p = point_of(ev.evaluate(start.x, go), start, {0, 0}, v);
  p.iterations = 1;
  ctx.count_iterations(1);
  ctx.store_point(p);
}

void run_optimise(const WalkerJob& job, JobContext& ctx) {
  ctx.announce(1);
  ctx.add_curve(0, "optimal gait", "speed");
  if (ctx.already_stored_points().count({0, 0})) return;
  const double v = job.speeds[0];
  nlp::SolverOptions solver = walker::distant_start_solver(job.solver);
  solver.on_iteration = solver_progress(
      ctx, {.parameter = v, .curve_id = 0, .points_done = 0, .points_total = 1, .message = "v = " + std::to_string(v) + " m/s"});
  solver.should_stop = stop_predicate(ctx);
  const GaitOptimum opt = walker::optimise_gait(job.model(), problem_at(job, v), solver, job.start);
  if (ctx.stop_reason() != StopReason::none) return;
  ctx.report_progress({.parameter = v, .curve_id = 0, .points_done = 0, .points_total = 1,
                       .message = "KKT sensitivities at v = " + std::to_string(v) + " m/s"});
  ctx.store_point(point_of(opt, {0, 0}, v, sensitivities_record(studies::optimum_sensitivities(job.model(), problem_at(job, v), opt, {}, stop_predicate(ctx)))));
}

void run_multistart(const WalkerJob& job, JobContext& ctx) {
  ctx.add_curve(0, "distinct optima, best first", "rank");
  // The multistart is deterministic (seeded starts): a resumed job takes the solves an interrupted
  // attempt finished from its checkpoints, solves the rest, and stores the optima not stored yet
  // (store_point ignores stored keys).
  const double v = job.speeds[0];
  const walker::WalkerModel<double> model = job.model();
  const walker::GaitProblemOptions po = problem_at(job, v);
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
    GaitOptimum opt;
    opt.summary = r.runs[o.starts.front()];
    opt.z = o.x;
    opt.gait = shape.gait_at(o.x);
    opt.start = "multistart run " + std::to_string(o.starts.front());
    storage::SolutionPoint p = point_of(opt, {0, static_cast<int>(k)}, static_cast<double>(k + 1));
    p.values["reached_by_starts"] = o.starts;
    p.values["kkt_successes"] = r.successes;
    p.values["starts"] = job.starts;
    p.values["wall_seconds"] = r.wall_seconds;
    ctx.store_point(p);
  }
}

JobKind walker_kind(const std::string& task, void (*run)(const WalkerJob&, JobContext&)) {
  return typed_job_kind<WalkerJob>(
      task, {"walker"}, walker_job_fields(false),
      [](const nlohmann::json& spec, const CommonJobFields& common) { return parse_walker_job(spec, common, false); },
      run, [task](const WalkerJob& job) { return walker_job_json(job, false, task == "multistart"); },
      [task](const WalkerJob& job) { return walker_job_cost(job, task, 1, 0); });
}

}  // namespace

JobKind walker_evaluate_kind() { return walker_kind("evaluate", run_evaluate); }
JobKind walker_optimise_kind() { return walker_kind("optimise", run_optimise); }
JobKind walker_multistart_kind() { return walker_kind("multistart", run_multistart); }

}  // namespace cyclopt::jobs
