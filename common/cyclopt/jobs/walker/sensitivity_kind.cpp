// The walker job kind "sensitivity" (issue 15 item 6; seed 001 section 10.1, Fig. 10.1): an
// optimal gait at one speed (from the automatic or a stored start, like optimise), stored with
// its KKT sensitivities (studies/optimum_sensitivities.hpp), then per parameter the +-relative_range
// continuation of studies/sensitivity.hpp from that optimum, its points stored, and one summary
// (records::SensitivitySummaryRecord) comparing the KKT linear prediction with it. Fields beside
// the walker ones of optimise (walker_job_spec.hpp):
//   "parameters": model parameter names (default: every parameter kkt_sensitivity covers whose
//                 value is not 0), "relative_range": in (0, 1) (default 0.1 = +-10 %),
//   "steps": continuation values per direction, [1, 50] (default 5).
//
// The verdict per parameter: "continuation stopped: <message>" when a direction did not reach
// the range; else "kink: <reasons>" when the KKT point flags a kink at p (weakly active rows), the
// predicted active-set change on a side is nearer than the range (the linear prediction holds
// only up to there), the continuation jumped to another curve, or the one-sided difference
// quotients at its smallest step h = range / steps do not bracket the KKT derivative; else
// "agrees". Bracketing, in units of the relative sensitivity s = p / f* df*/dp: for a smooth
// f*(p), q(+h) and q(-h) differ from df*/dp by the curvature term +-f'' h p / 2, on opposite sides,
// so s must lie in [min(s-, s+), max(s-, s+)] widened by kQuotientTolerance.

#include "cyclopt/jobs/solver_progress.hpp"
#include "cyclopt/jobs/walker/walker_job_cost.hpp"
#include "cyclopt/jobs/walker/walker_job_json.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/jobs/walker/walker_kinds.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"
#include "cyclopt/jobs/walker/walker_records.hpp"
#include "cyclopt/records/sensitivity_records.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/studies/kkt_sensitivity.hpp"
#include "cyclopt/studies/optimum_sensitivities.hpp"
#include "cyclopt/studies/sensitivity.hpp"
#include "cyclopt/walker/model_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

using records::ParameterSensitivityRecord;
using records::SensitivitySummaryRecord;

// The widening of the bracket: 2 % of |s| plus 1e-4 (absolute, relative sensitivity units).
constexpr double kQuotientRelativeTolerance = 0.02, kQuotientAbsoluteTolerance = 1e-4;

struct SensitivityJob {
  WalkerJob walker;
  // The study's options (seed 001 section 10.1: +-10 %): parameters, range, steps; the spec's
  // solver as the corrector. The job's observers are attached when it runs.
  studies::SensitivityOptions sensitivity;

  walker::GaitProblemOptions problem() const { return walker.problem_at(walker.speeds.front()); }
};

std::string percent(double relative) {
  char b[32];
  std::snprintf(b, sizeof b, "%+.3g %%", 100.0 * relative);
  return b;
}

std::string number_text(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", x);
  return b;
}

// The parameters a sensitivity job can vary: those kkt_sensitivity covers, with a nonzero value
// (the continuation varies p by relative amounts).
std::vector<std::string> admissible_parameters(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& po) {
  const Eigen::VectorXd values = walker::model_parameters(model);
  std::vector<std::string> out;
  for (const std::string& n : studies::sensitivity_parameters(model, po))
    if (values[walker::model_parameter_index(model, n)] != 0.0) out.push_back(n);
  return out;
}

SensitivityJob parse_sensitivity_job(const nlohmann::json& spec, const CommonJobFields& common) {
  SensitivityJob j;
  nlohmann::json walker = spec;
  for (const char* key : {"parameters", "relative_range", "steps"}) walker.erase(key);
  j.walker = parse_walker_job(walker, common, false);
  j.sensitivity.continuation.corrector = j.walker.solver;
  const std::vector<std::string> admissible = admissible_parameters(j.walker.model(), j.problem());
  if (spec.contains("parameters")) {
    const nlohmann::json& p = spec["parameters"];
    if (!p.is_array() || p.empty())
      throw SpecError("parameters", "must be a non-empty array of model parameter names; admissible: " + join(admissible));
    for (std::size_t i = 0; i < p.size(); ++i) {
      const std::string field = "parameters[" + std::to_string(i) + "]";
      if (!p[i].is_string() || std::find(admissible.begin(), admissible.end(), p[i].get<std::string>()) == admissible.end())
        throw SpecError(field, p[i].dump() + " is not a parameter with a sensitivity in this model (free, derived from "
                               "the density, or 0); admissible: " + join(admissible));
      if (std::find(j.sensitivity.parameters.begin(), j.sensitivity.parameters.end(), p[i].get<std::string>()) != j.sensitivity.parameters.end())
        throw SpecError(field, p[i].dump() + " is listed twice");
      j.sensitivity.parameters.push_back(p[i].get<std::string>());
    }
  } else {
    j.sensitivity.parameters = admissible;
  }
  if (spec.contains("relative_range")) {
    const nlohmann::json& r = spec["relative_range"];
    if (!r.is_number() || !(r.get<double>() > 0.0 && r.get<double>() < 1.0))
      throw SpecError("relative_range", "must be a number in (0, 1) (0.1: +-10 % as in seed 001 section 10.1), got " + r.dump());
    j.sensitivity.relative_range = r.get<double>();
  }
  j.sensitivity.steps = optional_integer(spec, "", "steps", 1, 50).value_or(j.sensitivity.steps);
  return j;
}

nlohmann::json sensitivity_job_json(const SensitivityJob& j) {
  nlohmann::json r = walker_job_json(j.walker, false, false);
  r["parameters"] = j.sensitivity.parameters;
  r["relative_range"] = j.sensitivity.relative_range;
  r["steps"] = j.sensitivity.steps;
  return r;
}

// One optimise plus, per parameter, a continuation over 2 (steps + 1) values.
JobCost sensitivity_cost(const SensitivityJob& j) {
  const JobCost optimise = walker_job_cost(j.walker, "optimise", 1, 0);
  const JobCost one = walker_job_cost(j.walker, "continuation", 2 * (j.sensitivity.steps + 1), 0);
  JobCost c = optimise;
  c.seconds = optimise.seconds + static_cast<double>(j.sensitivity.parameters.size()) * one.seconds;
  c.memory_bytes = std::max(optimise.memory_bytes, one.memory_bytes);
  c.field = "parameters";
  c.breakdown = "optimise " + duration_text(optimise.seconds) + " + " + std::to_string(j.sensitivity.parameters.size()) +
                " parameters x continuation of " + std::to_string(2 * (j.sensitivity.steps + 1)) + " values " + duration_text(one.seconds);
  return c;
}

// The continuation point at relative change `at` (within 1e-9), or nullptr.
const studies::SensitivityPoint* point_at(const studies::SensitivityCurve& c, double at) {
  for (const studies::SensitivityPoint& p : c.points)
    if (std::abs(p.relative_change - at) <= 1e-9) return &p;
  return nullptr;
}

// The comparison of the KKT sensitivity `k` (null: none) with the continuation (see the header).
SensitivitySummaryRecord compare(const ParameterSensitivityRecord* k, double objective, const studies::SensitivityCurve& c,
                                 double range, int steps, const std::optional<std::string>& kkt_unavailable) {
  SensitivitySummaryRecord s;
  s.parameter = c.parameter;
  s.value = c.base_value;
  s.relative_range = range;
  s.jumps = c.jumps;
  if (k) {
    s.derivative = k->derivative;
    s.relative = k->relative;
    s.kink = k->kink;
    s.predicted_decrease = -k->derivative * c.base_value * range;
    s.predicted_increase = k->derivative * c.base_value * range;
  }
  for (const studies::SensitivityPoint& p : c.points) {
    if (p.relative_change < 0 && !(p.relative_change >= s.reached_decrease)) {
      s.reached_decrease = p.relative_change;
      s.continuation_decrease = p.delta_objective;
    }
    if (p.relative_change > 0 && !(p.relative_change <= s.reached_increase)) {
      s.reached_increase = p.relative_change;
      s.continuation_increase = p.delta_objective;
    }
  }
  const double h = range / steps;
  if (const studies::SensitivityPoint* m = point_at(c, -h)) s.quotient_decrease = -m->delta_objective / (h * c.base_value);
  if (const studies::SensitivityPoint* p = point_at(c, h)) s.quotient_increase = p->delta_objective / (h * c.base_value);

  if (!c.message.empty() || !(std::abs(s.reached_decrease + range) <= 1e-9 && std::abs(s.reached_increase - range) <= 1e-9)) {
    s.verdict = "continuation stopped: " + (c.message.empty() ? std::string("did not reach +-") + percent(range) : c.message) +
                " (reached " + percent(s.reached_decrease) + " .. " + percent(s.reached_increase) + ")";
    return s;
  }
  if (!k) {
    s.verdict = "no KKT sensitivity: " + kkt_unavailable.value_or("not computed");
    return s;
  }
  std::vector<std::string> reasons;
  if (k->kink) {
    std::string rows;
    for (std::size_t i = 0; i < k->weakly_active.size() && i < 3; ++i) rows += (i ? ", " : "") + k->weakly_active[i];
    if (k->weakly_active.size() > 3) rows += " and " + std::to_string(k->weakly_active.size() - 3) + " more";
    reasons.push_back("the active set changes at p itself (" + (rows.empty() ? std::string("a multiplier is ~0") : rows) + ")");
  }
  for (const auto& [side, change] : {std::pair{-1.0, k->decrease}, std::pair{1.0, k->increase}})
    if (!k->kink && change.relative_change < range)
      reasons.push_back(change.constraint + (change.enters ? " enters" : " leaves") + " the active set at " +
                        percent(side * change.relative_change));
  if (c.jumps > 0) reasons.push_back("the continuation jumped to another solution curve " + std::to_string(c.jumps) + " time(s)");
  const double scale = c.base_value / objective;  // df/dp -> relative sensitivity
  const double lo = std::min(s.quotient_decrease, s.quotient_increase) * scale;
  const double hi = std::max(s.quotient_decrease, s.quotient_increase) * scale;
  const double tol = kQuotientRelativeTolerance * std::abs(k->relative) + kQuotientAbsoluteTolerance;
  const bool bracketed = k->relative >= lo - tol && k->relative <= hi + tol;
  if (!bracketed)
    reasons.push_back("the difference quotients at " + percent(-h) + " / " + percent(h) + " (" + number_text(lo) + " .. " +
                      number_text(hi) + " relative) do not bracket the KKT relative sensitivity " + number_text(k->relative));
  if (reasons.empty()) {
    s.verdict = "agrees";
  } else {
    s.verdict = "kink: " + join(reasons, "; ");
    if (bracketed) s.verdict += "; the difference quotients at +-" + percent(h).substr(1) + " still bracket the KKT derivative";
  }
  return s;
}

void run_sensitivity(const SensitivityJob& job, JobContext& ctx) {
  const int n = static_cast<int>(job.sensitivity.parameters.size());
  const double v = job.walker.speeds.front();
  ctx.announce(1 + n);
  ctx.add_curve(records::kSensitivityOptimumCurve, "optimal gait", "speed");
  ctx.add_curve(records::kSensitivitySummaryCurve, "KKT sensitivity against the " + percent(job.sensitivity.relative_range) +
                                                       " continuation, per parameter", "parameter index");
  for (int k = 0; k < n; ++k)
    ctx.add_curve(records::sensitivity_continuation_curve(k), job.sensitivity.parameters[static_cast<std::size_t>(k)] + ": continuation",
                  "relative change of " + job.sensitivity.parameters[static_cast<std::size_t>(k)]);
  const std::set<storage::PointKey> stored = ctx.already_stored_points();
  int done = 0;
  for (int k = 0; k < n; ++k) done += static_cast<int>(stored.count({records::kSensitivitySummaryCurve, k}));
  if (stored.count({records::kSensitivityOptimumCurve, 0}) && done == n) return;
  // A resumed job solves the optimum again (deterministic): its continuations start there.
  const walker::WalkerModel<double> model = job.walker.model();
  const walker::GaitProblemOptions po = job.problem();
  nlp::SolverOptions solver = job.walker.solver;
  solver.on_iteration = solver_progress(ctx, {.parameter = v, .curve_id = 0, .points_done = done, .points_total = 1 + n,
                                              .message = "optimum at v = " + number_text(v) + " m/s"});
  solver.should_stop = stop_predicate(ctx);
  const walker::GaitOptimum opt = walker::optimise_gait(model, po, solver, job.walker.start);
  if (ctx.stop_reason() != StopReason::none) return;
  ctx.report_progress({.parameter = v, .curve_id = 0, .points_done = done, .points_total = 1 + n,
                       .message = "KKT sensitivities of " + std::to_string(n) + " parameters"});
  const std::optional<records::KktSensitivitiesRecord> kkt = sensitivities_record(studies::optimum_sensitivities(model, po, opt, job.sensitivity.parameters, stop_predicate(ctx)));
  if (ctx.stop_reason() != StopReason::none) return;
  ctx.store_point(point_of(opt, {records::kSensitivityOptimumCurve, 0}, v, kkt));
  const bool converged = opt.summary.termination == nlp::Termination::converged;
  for (int k = 0; k < n; ++k) {
    const std::string& name = job.sensitivity.parameters[static_cast<std::size_t>(k)];
    if (stored.count({records::kSensitivitySummaryCurve, k})) continue;
    storage::SolutionPoint summary;
    summary.key = {records::kSensitivitySummaryCurve, k};
    summary.parameter = k;
    if (!converged) {
      SensitivitySummaryRecord s;
      s.parameter = name;
      s.relative_range = job.sensitivity.relative_range;
      s.verdict = std::string("not computed: the optimisation ended ") + nlp::to_string(opt.summary.termination);
      summary.status = "no optimum";
      summary.set_values(s);
      ctx.store_point(summary);
      continue;
    }
    ctx.report_progress({.parameter = static_cast<double>(k), .curve_id = records::sensitivity_continuation_curve(k),
                         .points_done = done, .points_total = 1 + n,
                         .message = name + " (" + std::to_string(k + 1) + "/" + std::to_string(n) + "): " +
                                    percent(job.sensitivity.relative_range).substr(1) + " continuation in " + std::to_string(job.sensitivity.steps) +
                                    " steps each way"});
    studies::SensitivityOptions so = job.sensitivity;
    so.parameters = {name};
    so.continuation.corrector.on_iteration = solver_progress(
        ctx, {.parameter = static_cast<double>(k), .curve_id = records::sensitivity_continuation_curve(k), .points_done = done,
              .points_total = 1 + n, .message = name + ": continuation"});
    so.continuation.corrector.should_stop = stop_predicate(ctx);
    const studies::SensitivityCurve curve = studies::sensitivity(model, po, opt.z, so).front();
    if (ctx.stop_reason() != StopReason::none) return;
    for (std::size_t i = 0; i < curve.points.size(); ++i) {
      const studies::SensitivityPoint& p = curve.points[i];
      storage::SolutionPoint sp;
      sp.key = {records::sensitivity_continuation_curve(k), static_cast<int>(i)};
      sp.parameter = p.relative_change;
      sp.objective = opt.summary.objective + p.delta_objective;
      sp.status = "ok";
      sp.required = false;  // the continuation may stop before the range; the summary says so
      sp.set_values(records::SensitivityStepRecord{.parameter = name,
                                                 .value = curve.base_value * (1.0 + p.relative_change),
                                                 .relative_change = p.relative_change,
                                                 .delta_objective = p.delta_objective,
                                                 .curve_id = p.curve_id});
      ctx.store_point(sp);
    }
    const ParameterSensitivityRecord* ks = nullptr;
    if (kkt && !kkt->unavailable)
      for (const ParameterSensitivityRecord& r : kkt->parameters)
        if (r.name == name) ks = &r;
    const SensitivitySummaryRecord s = compare(ks, opt.summary.objective, curve, job.sensitivity.relative_range, job.sensitivity.steps,
                                               kkt ? kkt->unavailable : std::nullopt);
    // The comparison counts as a solution when both sides reached the range (agrees or kink).
    summary.status = s.verdict == "agrees" || s.verdict.rfind("kink", 0) == 0 ? "ok" : "incomplete";
    summary.set_values(s);
    ctx.store_point(summary);
    ++done;
  }
}

}  // namespace

JobKind sensitivity_kind() {
  std::vector<std::string> fields = walker_job_fields(false);
  fields.erase(std::remove(fields.begin(), fields.end(), "multistart"), fields.end());
  fields.insert(fields.end(), {"parameters", "relative_range", "steps"});
  return typed_job_kind<SensitivityJob>("sensitivity", {"walker"}, fields, parse_sensitivity_job, run_sensitivity,
                                        sensitivity_job_json, sensitivity_cost);
}

}  // namespace cyclopt::jobs
