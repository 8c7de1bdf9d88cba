#include "cyclopt/jobs/walker/walker_continuation_kinds.hpp"

#include "cyclopt/continuation/continuation_solver.hpp"
#include "cyclopt/jobs/solver_progress.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/jobs/walker/sweep_checkpoints.hpp"
#include "cyclopt/jobs/walker/sweep_fields.hpp"
#include "cyclopt/service/value_range.hpp"
#include "cyclopt/jobs/walker/walker_job_cost.hpp"
#include "cyclopt/jobs/walker/walker_job_json.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"
#include "cyclopt/studies/speed_sweep.hpp"
#include "cyclopt/studies/walker_family.hpp"
#include "cyclopt/walker/model_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

using continuation::CurvePoint;

struct ContinuationJob {
  WalkerJob walker;
  continuation::ContinuationOptions options;
  std::string parameter = "speed";
  std::vector<double> values;  // p_0, p_1, ...: the speeds, or "continuation.values"
  std::vector<double> seed_speeds{0.3, 1.3, 2.3};
  int coarse_points = studies::SpeedSweepOptions{}.coarse_points;  // a sweep's multistarts
  int runner_ups = studies::SpeedSweepOptions{}.runner_ups;        // a sweep's seed-speed optima continued
  int closure_passes = studies::EnvelopeClosureOptions{}.max_passes;  // a sweep's closure (0: off)
};

ContinuationJob parse_continuation_job(const nlohmann::json& spec, const CommonJobFields& common) {
  ContinuationJob j;
  j.walker = parse_walker_job(spec, common, true);
  j.options.corrector = j.walker.solver;
  j.values = j.walker.speeds;
  if (!spec.contains("continuation")) return j;
  const nlohmann::json& c = object_value(spec["continuation"], "continuation");
  reject_unknown_keys(c, "continuation",
                      {"predictor", "predictor_hessian", "fixed_step", "min_trust_region", "max_trust_region", "parameter",
                       "values", "seed_speeds", "coarse_points", "runner_ups", "closure_passes"});
  if (c.contains("predictor"))
    j.options.predictor = continuation::parse_predictor(enum_value(c["predictor"], "continuation.predictor", continuation::predictor_names()));
  if (c.contains("predictor_hessian"))
    j.options.reuse_predictor_hessian = enum_value(c["predictor_hessian"], "continuation.predictor_hessian",
                                                   {continuation::predictor_hessian_name(true),
                                                    continuation::predictor_hessian_name(false)}) ==
                                        continuation::predictor_hessian_name(true);
  j.options.fixed_step = optional_number(c, "continuation", "fixed_step", 0.0, 1e3).value_or(0.0);
  j.options.min_trust_region = optional_number(c, "continuation", "min_trust_region", 1e-9, 1e3).value_or(j.options.min_trust_region);
  j.options.max_trust_region = optional_number(c, "continuation", "max_trust_region", 0.0, 1e3).value_or(0.0);
  if (c.contains("seed_speeds"))
    j.seed_speeds = parse_value_range(c["seed_speeds"], "continuation.seed_speeds", kMinWalkingSpeed, kMaxWalkingSpeed);
  j.coarse_points = parse_coarse_points(c, j.coarse_points);
  j.runner_ups = parse_runner_ups(c, j.runner_ups);
  j.closure_passes = parse_closure_passes(c, j.closure_passes);
  if (c.contains("parameter")) {
    std::vector<std::string> names = walker::model_parameter_names(j.walker.model());
    names.insert(names.begin(), "speed");
    j.parameter = enum_value(c["parameter"], "continuation.parameter", names);
  }
  if (j.parameter != "speed") {
    if (!c.contains("values")) throw SpecError("continuation.values", "is required when continuation.parameter is not speed");
    const walker::WalkerModel<double> model = j.walker.model();
    const int index = walker::model_parameter_index(model, j.parameter);
    const auto [lo, hi] = walker::model_parameter_range(model, index);
    j.values = parse_value_range(c["values"], "continuation.values", lo, hi);
    if (std::find(j.walker.problem.free_parameters.begin(), j.walker.problem.free_parameters.end(), j.parameter) !=
        j.walker.problem.free_parameters.end())
      throw SpecError("continuation.parameter", "must not be one of free_parameters");
    if (walker::follows_foot_geometry(model, index))
      throw SpecError("continuation.parameter", "'" + j.parameter +
                                                    "' follows the foot geometry when foot.density is given (appendix "
                                                    "E); continue a foot parameter or \"density\" instead");
  }
  if (j.values.size() < 2) throw SpecError(j.parameter == "speed" ? "speeds" : "continuation.values", "needs at least two values");
  return j;
}

// The resolved spec (resolved_spec.hpp): the walker fields and the whole "continuation" block;
// seed_speeds, coarse_points, runner_ups and the multistart only for a sweep, which draws random starts at them.
nlohmann::json continuation_job_json(const ContinuationJob& j, bool sweep) {
  nlohmann::json r = walker_job_json(j.walker, true, sweep);
  nlohmann::json c = {{"predictor", continuation::to_string(j.options.predictor)},
                      {"predictor_hessian", continuation::predictor_hessian_name(j.options.reuse_predictor_hessian)},
                      {"fixed_step", j.options.fixed_step},
                      {"min_trust_region", j.options.min_trust_region},
                      {"max_trust_region", j.options.max_trust_region},
                      {"parameter", j.parameter}};
  if (j.parameter != "speed") c["values"] = j.values;
  if (sweep)
    c["seed_speeds"] = j.seed_speeds, c["coarse_points"] = j.coarse_points, c["runner_ups"] = j.runner_ups,
    c["closure_passes"] = j.closure_passes;
  r["continuation"] = c;
  return r;
}

// Stores curve points as they come: curve_index = curve id + offset, numbered along the curve.
// grid_points_required: the points on the requested grid are what the job was asked for
// (a continuation job), rather than a by-product (a sweep's runs, whose best rows are).
class CurveStore {
 public:
  CurveStore(JobContext& ctx, const continuation::ParametricProblem& family, int offset, bool grid_points_required)
      : ctx_(ctx), family_(family), offset_(offset), grid_points_required_(grid_points_required) {}

  bool operator()(const CurvePoint& c) {
    const int curve = c.curve_id + offset_;
    if (!counts_.count(curve)) ctx_.add_curve(curve, "solution curve " + std::to_string(c.curve_id), family_.parameter_name);
    const int index = counts_[curve]++;
    storage::SolutionPoint p = point(c, {curve, index});
    p.required = grid_points_required_ && c.on_grid;
    ctx_.store_point(p);
    return ctx_.stop_reason() == StopReason::none;
  }

  storage::SolutionPoint point(const CurvePoint& c, storage::PointKey key) const { return point_of(family_, c, key); }

 private:
  JobContext& ctx_;
  const continuation::ParametricProblem& family_;
  const int offset_;
  const bool grid_points_required_;
  std::map<int, int> counts_;
};

void run_continuation(const ContinuationJob& job, JobContext& ctx) {
  const walker::WalkerModel<double> model = job.walker.model();
  walker::GaitProblemOptions po = job.walker.problem;
  po.speed = job.walker.speeds.front();
  ctx.announce(static_cast<int>(job.values.size()));
  continuation::ContinuationOptions options = job.options;
  options.corrector.on_iteration = solver_progress(ctx, {.points_total = -1, .message = "continuation over " + job.parameter});
  options.corrector.should_stop = stop_predicate(ctx);
  const continuation::ParametricProblem family = studies::walker_family(model, po, job.parameter);
  walker::GaitProblemOptions first = po;
  if (job.parameter == "speed") first.speed = job.values.front();
  Eigen::VectorXd x0;
  if (job.walker.start) {
    x0 = walker::GaitProblem(model, first).initial_point(*job.walker.start);
  } else {  // the first point from the automatic starting gait (Algorithm 2, step 1 solves it)
    walker::StartingGaitOptions so;
    so.speed = first.speed;
    const walker::StartingGait sg = walker::starting_gait(walker::GaitEvaluator(model), so);
    if (!sg.real) throw std::runtime_error("no starting gait at " + std::to_string(first.speed) + " m/s: " + sg.message);
    x0 = walker::GaitProblem(model, first).initial_point(sg.x);
  }
  CurveStore store(ctx, family, 0, true);
  const continuation::ContinuationResult r =
      continuation::continue_solution(family, x0, job.values, options, {}, [&](const CurvePoint& c) { return store(c); });
  if (ctx.stop_reason() != StopReason::none) return;
  if (r.points.empty() || !r.points.front().converged) throw std::runtime_error("continuation: " + r.message);
}

void run_sweep(const ContinuationJob& job, JobContext& ctx) {
  const walker::WalkerModel<double> model = job.walker.model();
  studies::SpeedSweepOptions so;
  so.speeds = job.values;
  so.seed_speeds = job.seed_speeds;
  so.coarse_points = job.coarse_points;
  so.runner_ups = job.runner_ups;
  so.starts = job.walker.starts;
  so.seeds = job.walker.seeds;
  so.closure.max_passes = std::max(job.closure_passes, 1);
  so.closure.enabled = job.closure_passes > 0;
  so.scale = job.walker.scale;
  so.continuation = job.options;
  PhaseProgress progress(ctx, {.points_total = static_cast<int>(so.speeds.size()), .message = "speed sweep"});
  so.continuation.corrector.on_iteration = progress.iterations();
  so.on_progress = [&](const studies::SweepProgress& p) { progress.set(sweep_progress_report(p, "speed sweep")); };
  so.continuation.corrector.should_stop = stop_predicate(ctx);
  so.journal = sweep_journal(ctx);  // a resumed sweep reuses what an earlier attempt finished
  const continuation::ParametricProblem family = studies::walker_family(model, job.walker.problem, "speed");
  ctx.announce(static_cast<int>(so.speeds.size()));
  CurveStore store(ctx, family, 1, false);
  const studies::SpeedSweepResult r =
      studies::speed_sweep(model, job.walker.problem, so, [&](const CurvePoint& c) { return store(c); });
  if (ctx.stop_reason() != StopReason::none) return;
  ctx.add_curve(0, "best solution per speed", "speed");
  for (std::size_t i = 0; i < r.best.size(); ++i) {
    const studies::BestPoint& b = r.best[i];
    storage::SolutionPoint p;
    if (b.found) {
      p = store.point(b.point, {0, static_cast<int>(i)});  // required, as every best row
      p.values["found_by"] = studies::describe(b);  // which sweep step found the point
    } else {
      p.key = {0, static_cast<int>(i)};
      p.parameter = b.speed;
      p.status = "not found";
      p.values["reason"] = b.reason;
    }
    p.values["sweep_seconds"] = r.seconds;
    p.values["curves"] = r.curves;
    // How sure the point is: the closure's passes here, and the spread between the seeds' searches.
    p.values["closure"] = studies::describe(r.closure);
    p.values["closure_passes"] = b.closure_passes;
    if (std::isfinite(r.seed_spread[i])) p.values["seed_spread"] = r.seed_spread[i];
    // This attempt's work: what it solved and what it took over from earlier attempts.
    p.values["attempt"] = {{"multistart_solves", r.multistart_solves}, {"resumed_solves", r.resumed_solves},
                           {"computed_runs", r.computed_runs}, {"resumed_runs", r.resumed_runs}};
    ctx.store_point(p);
  }
}

JobKind continuation_kind(const std::string& task, void (*run)(const ContinuationJob&, JobContext&)) {
  std::vector<std::string> fields = walker_job_fields(true);
  fields.push_back("continuation");
  return typed_job_kind<ContinuationJob>(task, {"walker"}, fields, parse_continuation_job, run,
                                         [task](const ContinuationJob& j) { return continuation_job_json(j, task == "sweep"); },
                                         [task](const ContinuationJob& j) {
                                           return walker_job_cost(j.walker, task, static_cast<int>(j.values.size()),
                                                                  static_cast<int>(j.seed_speeds.size()));
                                         });
}

}  // namespace

JobKind walker_continuation_kind() { return continuation_kind("continuation", run_continuation); }
JobKind walker_sweep_kind() { return continuation_kind("sweep", run_sweep); }

}  // namespace cyclopt::jobs
