#include "cyclopt/service/walker_job_kinds.hpp"

#include "cyclopt/nlp/multistart.hpp"
#include "cyclopt/service/walker_job_spec.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"

#include <cmath>

namespace cyclopt::service {

namespace {

using walker::GaitOptimum;

walker::GaitProblemOptions problem_at(const WalkerJob& job, double speed) {
  walker::GaitProblemOptions o = job.problem;
  o.speed = speed;
  return o;
}

storage::SolutionPoint point_of(const walker::PeriodicGait<double>& gait, storage::PointKey key, double speed) {
  storage::SolutionPoint p;
  p.key = key;
  p.parameter = speed;
  nlohmann::json g = walker::gait_to_json(gait, true);
  if (g.contains("trajectory")) {
    p.trajectory = g["trajectory"];
    g.erase("trajectory");
  }
  p.values["gait"] = g;
  if (gait.real) {
    p.objective = gait.objective;
    p.constraint_violation = std::max({0.0, std::abs(gait.speed_equality), gait.inequalities.maxCoeff()});
  }
  p.status = gait.real ? "ok" : "no real solution";
  return p;
}

storage::SolutionPoint point_of(const GaitOptimum& opt, storage::PointKey key, double speed) {
  storage::SolutionPoint p = point_of(opt.gait, key, speed);
  p.iterations = opt.summary.iterations;
  p.status = nlp::to_string(opt.summary.termination);
  p.values["solver"] = walker::summary_to_json(opt.summary);
  p.values["start"] = opt.start;
  p.values["start_objective"] = opt.start_objective;
  return p;
}

// Solver options whose iteration callback reports progress and honours stop requests.
nlp::SolverOptions reporting(const WalkerJob& job, JobContext& ctx, double speed, int done, int total) {
  nlp::SolverOptions o = job.solver;
  o.on_iteration = [&ctx, speed, done, total](const nlp::IterationReport& r) {
    ctx.count_iterations(1);
    ctx.report_progress({.iteration = r.iteration,
                         .objective = r.objective,
                         .constraint_violation = r.constraint_violation,
                         .parameter = speed,
                         .curve_id = 0,
                         .points_done = done,
                         .points_total = total,
                         .message = "v = " + std::to_string(speed) + " m/s"});
    return ctx.stop_reason() == StopReason::none;
  };
  return o;
}

void run_evaluate(const nlohmann::json& spec, JobContext& ctx) {
  const WalkerJob job = parse_walker_job(spec, false);
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
  storage::SolutionPoint p = point_of(ev.evaluate(start.x, go), {0, 0}, v);
  p.values["x"] = std::vector<double>(start.x.data(), start.x.data() + start.x.size());
  p.values["start"] = start.origin;
  p.iterations = 1;
  ctx.count_iterations(1);
  ctx.store_point(p);
}

void run_optimise(const nlohmann::json& spec, JobContext& ctx) {
  const WalkerJob job = parse_walker_job(spec, false);
  ctx.announce(1);
  ctx.add_curve(0, "optimal gait", "speed");
  if (ctx.already_stored_points().count({0, 0})) return;
  const double v = job.speeds[0];
  const GaitOptimum opt = walker::optimise_gait(job.model(), problem_at(job, v), reporting(job, ctx, v, 0, 1), job.start);
  if (ctx.stop_reason() != StopReason::none) return;
  ctx.store_point(point_of(opt, {0, 0}, v));
}

void run_multistart(const nlohmann::json& spec, JobContext& ctx) {
  const WalkerJob job = parse_walker_job(spec, false);
  ctx.add_curve(0, "distinct optima, best first", "rank");
  // The multistart is deterministic (seeded starts), so a resumed job recomputes it and stores the
  // optima an interrupted attempt had not stored yet (store_point ignores stored keys).
  const double v = job.speeds[0];
  const walker::WalkerModel<double> model = job.model();
  const walker::GaitProblemOptions po = problem_at(job, v);
  const walker::GaitEvaluator ev(model);
  const Eigen::VectorXd centre = walker::gait_start(ev, v, job.start).x;
  const walker::GaitProblem shape(model, po);
  nlp::MultistartOptions mo;
  mo.num_starts = job.starts;
  mo.base_seed = job.seed;
  mo.solver = job.solver;
  mo.solver.on_iteration = [&ctx](const nlp::IterationReport&) { return ctx.stop_reason() == StopReason::none; };
  ctx.report_progress({.parameter = v, .curve_id = 0, .points_total = -1,
                       .message = std::to_string(job.starts) + " starts at v = " + std::to_string(v) + " m/s"});
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
    p.values["x"] = std::vector<double>(o.x.data(), o.x.data() + o.x.size());
    ctx.store_point(p);
  }
}

void run_sweep(const nlohmann::json& spec, JobContext& ctx) {
  const WalkerJob job = parse_walker_job(spec, true);
  const int n = static_cast<int>(job.speeds.size());
  ctx.announce(n);
  ctx.add_curve(0, "optimal gaits over speed", "speed");
  const std::set<storage::PointKey> done = ctx.already_stored_points();
  const walker::WalkerModel<double> model = job.model();
  std::optional<Eigen::VectorXd> warm = job.start;
  int stored = static_cast<int>(done.size());
  for (int i = 0; i < n; ++i) {
    if (done.count({0, i})) {
      warm.reset();  // a resumed sweep restarts the warm-start chain from the automatic start
      continue;
    }
    if (ctx.stop_reason() != StopReason::none) return;
    const double v = job.speeds[i];
    GaitOptimum opt = walker::optimise_gait(model, problem_at(job, v), reporting(job, ctx, v, stored, n), warm);
    if (!opt.summary.success() && warm && ctx.stop_reason() == StopReason::none) {
      GaitOptimum cold = walker::optimise_gait(model, problem_at(job, v), reporting(job, ctx, v, stored, n));
      if (cold.summary.success() || !opt.gait.real) opt = std::move(cold);
    }
    if (ctx.stop_reason() != StopReason::none) return;
    storage::SolutionPoint p = point_of(opt, {0, i}, v);
    p.values["x"] = std::vector<double>(opt.z.data(), opt.z.data() + opt.z.size());
    if (ctx.store_point(p)) ++stored;
    if (opt.summary.success()) warm = opt.z.head(opt.z.size() - static_cast<int>(job.problem.free_parameters.size()));
    else warm.reset();
  }
}

JobKind walker_kind(const std::string& task, bool sweep, void (*run)(const nlohmann::json&, JobContext&)) {
  return {task, {"walker"}, walker_job_fields(sweep),
          [sweep](const nlohmann::json& spec) { parse_walker_job(spec, sweep); }, run};
}

}  // namespace

JobKind walker_evaluate_kind() { return walker_kind("evaluate", false, run_evaluate); }
JobKind walker_optimise_kind() { return walker_kind("optimise", false, run_optimise); }
JobKind walker_multistart_kind() { return walker_kind("multistart", false, run_multistart); }
JobKind walker_sweep_kind() { return walker_kind("sweep", true, run_sweep); }

}  // namespace cyclopt::service
