// Job kind "continuation" (scene walker; seed 001 Algorithm 2): one solution curve over "speeds"
// (p_0 first, then the requested values; the mean speed) or, with "continuation": {"parameter":
// "l_HM", "values": "0.20:0.01:0.25"}, over a model parameter at the first of "speeds". The walker
// fields of walker_job_spec.hpp and the "continuation" block of continuation_fields.hpp.
//
// Storage: solution curve c is curve_index c; points are numbered in the order solved along their
// curve and stored the moment they exist, each with its curve id, whether it is a requested value,
// the predictor's tries, steps and kappa (7.2) (walker_points.hpp). The computation is
// deterministic, so a resumed job recomputes and stores only the missing points.
#include "cyclopt/jobs/solver_progress.hpp"
#include "cyclopt/jobs/walker/continuation_fields.hpp"
#include "cyclopt/jobs/walker/walker_job_cost.hpp"
#include "cyclopt/jobs/walker/walker_job_json.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/jobs/walker/walker_kinds.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"
#include "cyclopt/service/value_range.hpp"
#include "cyclopt/studies/walker_family.hpp"
#include "cyclopt/walker/model_parameters.hpp"

#include <algorithm>
#include <stdexcept>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

struct ContinuationJob {
  WalkerJob walker;
  continuation::ContinuationOptions options;  // the corrector is the spec's solver
  std::string parameter = "speed";
  std::vector<double> values;  // p_0, p_1, ...: the speeds, or "continuation.values"
};

ContinuationJob parse_continuation_job(const nlohmann::json& spec, const CommonJobFields& common) {
  ContinuationJob j;
  j.walker = parse_walker_job(spec, common, true);
  j.options.corrector = j.walker.solver;
  j.values = j.walker.speeds;
  const walker::WalkerModel<double> model = j.walker.model();
  std::vector<std::string> parameters = walker::model_parameter_names(model);
  parameters.insert(parameters.begin(), "speed");
  const ContinuedParameter continued = parse_curve_continuation(spec, j.options, parameters);
  j.parameter = continued.name;
  if (j.parameter != "speed") {
    if (!continued.values) throw SpecError("continuation.values", "is required when continuation.parameter is not speed");
    const int index = walker::model_parameter_index(model, j.parameter);
    const auto [lo, hi] = walker::model_parameter_range(model, index);
    j.values = parse_value_range(*continued.values, "continuation.values", lo, hi);
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

// The resolved spec (resolved_spec.hpp): the walker fields and the continuation block.
nlohmann::json continuation_job_json(const ContinuationJob& j) {
  nlohmann::json r = walker_job_json(j.walker, true, false);
  r["continuation"] = curve_continuation_json(j.options, j.parameter);
  if (j.parameter != "speed") r["continuation"]["values"] = j.values;
  return r;
}

void run_continuation(const ContinuationJob& job, JobContext& ctx) {
  const walker::WalkerModel<double> model = job.walker.model();
  const walker::GaitProblemOptions po = job.walker.problem_at(job.walker.speeds.front());
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
  const continuation::ContinuationResult r = continuation::continue_solution(
      family, x0, job.values, options, {}, [&](const continuation::CurvePoint& c) { return store(c); });
  if (ctx.stop_reason() != StopReason::none) return;
  if (r.points.empty() || !r.points.front().converged) throw std::runtime_error("continuation: " + r.message);
}

}  // namespace

JobKind continuation_kind() {
  std::vector<std::string> fields = walker_job_fields(true);
  fields.push_back("continuation");
  return typed_job_kind<ContinuationJob>("continuation", {"walker"}, fields, parse_continuation_job, run_continuation,
                                         continuation_job_json, [](const ContinuationJob& j) {
                                           return walker_job_cost(j.walker, "continuation", static_cast<int>(j.values.size()), 0);
                                         });
}

}  // namespace cyclopt::jobs
