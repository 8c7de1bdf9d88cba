#include "cyclopt/service/foot_comparison_kind.hpp"

#include "cyclopt/foot/fitted_feet.hpp"
#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/records/foot_comparison_records.hpp"
#include "cyclopt/service/foot_sweep_points.hpp"
#include "cyclopt/service/solver_progress.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/service/sweep_fields.hpp"
#include "cyclopt/service/walker_job_cost.hpp"
#include "cyclopt/service/walker_job_json.hpp"
#include "cyclopt/service/walker_job_spec.hpp"
#include "cyclopt/studies/foot_comparison.hpp"
#include "cyclopt/studies/walker_family.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <set>
#include <stdexcept>

namespace cyclopt::service {
namespace {

struct ComparisonJob {
  WalkerJob walker;                       // the common fields; walker.foot is the reference
  std::vector<foot::FootSpec> feet;       // the reference first, then the compared feet
  SweepFields sweeps;                     // "continuation"
};

// A compared foot is known by its preset name, else by its spec's name, else by its field path.
// That name becomes its spec's name, so that the resolved spec (the feet as full parameters)
// names the feet as the submitted one did.
foot::FootSpec named(foot::FootSpec spec, const nlohmann::json& v, const std::string& path) {
  if (v.is_string()) spec.name = v.get<std::string>();
  else if (spec.name.empty()) spec.name = path;
  return spec;
}

ComparisonJob parse_comparison_job(const nlohmann::json& spec, const CommonJobFields& common_fields) {
  for (const char* key : {"foot", "start", "free_parameters"})
    if (spec.contains(key))
      throw SpecError(key, std::string("is not a field of foot_comparison (") +
                               (std::string(key) == "foot" ? "give the feet as \"feet\" and \"reference\""
                                                           : "feet of different models share no gait or foot parameters") +
                               ")");
  nlohmann::json common = spec;
  common.erase("feet");
  common.erase("reference");
  common["foot"] = spec.contains("reference") ? spec["reference"] : nlohmann::json("point");
  ComparisonJob j;
  try {
    j.walker = parse_walker_job(common, common_fields, true);
  } catch (const SpecError& e) {
    if (e.field().rfind("foot", 0) != 0) throw;
    throw SpecError("reference" + e.field().substr(4), e.what());
  }
  if (j.walker.speeds.size() < 2) throw SpecError("speeds", "needs at least two values");
  j.walker.foot = named(j.walker.foot, common["foot"], "reference");
  j.feet.push_back(j.walker.foot);
  if (spec.contains("feet")) {
    const nlohmann::json& f = spec["feet"];
    if (!f.is_array() || f.empty() || f.size() > 64)
      throw SpecError("feet", "must be an array of 1-64 foot preset names or foot specs");
    for (std::size_t i = 0; i < f.size(); ++i) {
      const std::string path = "feet[" + std::to_string(i) + "]";
      j.feet.push_back(named(foot_value(f[i], path), f[i], path));
    }
  } else {  // seed 001 section 9.2
    for (const foot::FittedFoot* f : foot::select_fitted_feet({.section_9_2_only = true})) {
      j.feet.push_back(f->spec);
      j.feet.back().name = f->name();
    }
  }
  j.sweeps = parse_sweep_fields(spec);
  std::set<std::string> seen;
  for (std::size_t i = 0; i < j.feet.size(); ++i)
    if (!seen.insert(j.feet[i].name).second)
      throw SpecError(i == 0 ? "reference" : "feet[" + std::to_string(i - 1) + "]",
                      "foot '" + j.feet[i].name + "' is compared twice");
  return j;
}

void run_comparison(const ComparisonJob& job, JobContext& ctx) {
  const int feet = static_cast<int>(job.feet.size());
  const int speeds = static_cast<int>(job.walker.speeds.size());
  std::vector<studies::ComparedFoot> compared;
  for (int k = 0; k < feet; ++k) {
    WalkerJob w = job.walker;
    w.foot = job.feet[static_cast<std::size_t>(k)];
    compared.push_back({job.feet[static_cast<std::size_t>(k)].name, w.model()});
  }
  studies::FootComparisonOptions o;
  o.reference = 0;
  o.sweep = sweep_options(job.walker, job.sweeps, job.walker.starts);
  o.sweep.continuation.corrector.should_stop = stop_predicate(ctx);
  ctx.announce(feet * speeds + speeds + feet);
  ctx.add_curve(0, "best foot per speed", "speed");
  for (int k = 0; k < feet; ++k)
    ctx.add_curve(1 + k, "foot " + job.feet[static_cast<std::size_t>(k)].name + (k == 0 ? " (reference)" : ""), "speed");
  ctx.add_curve(feet + 1, "mean f_mech per foot", "curve");
  std::vector<std::vector<storage::SolutionPoint>> stored(static_cast<std::size_t>(feet));
  std::atomic<std::size_t> running = 0;  // the foot being swept (read by multistart workers too)
  const auto started = std::chrono::steady_clock::now();
  std::atomic<double> feet_seconds = 0.0;  // of the feet swept
  const auto on_foot = [&](std::size_t k, const studies::FootSweepSummary& s, const studies::SpeedSweepResult&) {
    const studies::ParametricProblem family = studies::walker_family(compared[k].model, job.walker.problem, "speed");
    for (storage::SolutionPoint& p : best_points(family, s, 1 + static_cast<int>(k))) {
      ctx.store_point(p);
      stored[k].push_back(std::move(p));
    }
    running = std::min(k + 1, compared.size() - 1);
    feet_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return ctx.stop_reason() == StopReason::none;
  };
  // Progress names the foot being swept and the phase of its sweep; the ETA is that sweep's plus
  // the feet still to sweep at the mean time of the feet swept so far.
  PhaseProgress progress(ctx, {.curve_id = 1, .points_total = feet * speeds});
  o.sweep.continuation.corrector.on_iteration = progress.iterations();
  o.sweep.on_progress = [&](const studies::SweepProgress& sp) {
    const std::size_t k = running;
    ProgressReport r = sweep_progress_report(
        sp, "foot " + std::to_string(k + 1) + "/" + std::to_string(feet) + " " + job.feet[k].name);
    r.curve_id = 1 + static_cast<int>(k);
    r.points_done = static_cast<int>(k) * speeds + sp.speeds_reached;
    r.points_total = feet * speeds;
    const double per_foot =
        k > 0 ? feet_seconds / static_cast<double>(k)
              : std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() + sp.eta_seconds;
    r.eta_seconds = sp.eta_seconds + static_cast<double>(feet - 1 - static_cast<int>(k)) * per_foot;
    progress.set(r);
  };
  const auto on_point = [&](std::size_t k, const continuation::CurvePoint&) {
    running = k;
    return ctx.stop_reason() == StopReason::none;
  };
  const studies::FootComparisonResult r =
      studies::compare_feet(compared, job.walker.problem, o, on_point, on_foot);
  if (ctx.stop_reason() != StopReason::none) return;
  for (int i = 0; i < speeds; ++i) {
    const int best = r.best_foot[static_cast<std::size_t>(i)];
    const double ref = r.feet[0].f_mech[static_cast<std::size_t>(i)];
    storage::SolutionPoint p;
    records::ComparedSpeedRecord c;
    if (best < 0) {
      p.key = {0, i};
      p.parameter = job.walker.speeds[static_cast<std::size_t>(i)];
      p.status = "not found";
      c.reason = "no compared foot has a point at this speed";
    } else {
      p = stored[static_cast<std::size_t>(best)][static_cast<std::size_t>(i)];
      p.key = {0, i};
      c = p.values.get<records::ComparedSpeedRecord>();
      if (std::isfinite(ref) && ref > 0.0) c.saving = 1.0 - r.envelope_f_mech[static_cast<std::size_t>(i)] / ref;
    }
    c.reference_f_mech = ref;
    p.values.update(nlohmann::json(c));
    ctx.store_point(p);
  }
  for (int k = 0; k < feet; ++k) {
    const studies::FootSweepSummary& s = r.feet[static_cast<std::size_t>(k)];
    storage::SolutionPoint p;
    p.key = {feet + 1, k};
    p.parameter = 1 + k;
    p.objective = s.mean_f_mech;
    p.status = s.common_speeds > 0 ? "ok" : "no common speeds";
    records::ComparedFootRecord f;
    f.foot = s.name;
    f.reference = k == 0;
    f.mean_f_mech = s.mean_f_mech;
    f.saving = s.saving;
    f.common_speeds = s.common_speeds;
    f.speeds_found = s.speeds_found;
    f.speeds = speeds;
    f.best_fitted = k == r.best_mean_foot;
    f.sweep_seconds = s.seconds;
    f.curves = s.curves;
    f.foot_spec = io::to_json(job.feet[static_cast<std::size_t>(k)]);
    if (k == 0) {
      f.envelope_saving = r.envelope_saving;
      f.envelope_common_speeds = r.envelope_common_speeds;
      f.comparison_seconds = r.seconds;
    }
    p.values = f;
    ctx.store_point(p);
  }
}

// The resolved spec (resolved_spec.hpp): the walker fields of a sweep but "foot" and
// "free_parameters" (not fields of this kind), the reference and the feet as their full
// parameters and names (the 16 of section 9.2 when none were given), the continuation block.
nlohmann::json comparison_job_json(const ComparisonJob& j) {
  nlohmann::json r = walker_job_json(j.walker, true, true);
  r.erase("foot");
  r.erase("free_parameters");
  r["reference"] = io::to_json(j.feet.front());
  r["feet"] = nlohmann::json::array();
  for (std::size_t k = 1; k < j.feet.size(); ++k) r["feet"].push_back(io::to_json(j.feet[k]));
  r["continuation"] = sweep_fields_json(j.sweeps);
  return r;
}

// One speed sweep per foot, one after the other.
JobCost comparison_cost(const ComparisonJob& j) {
  JobCost total;
  for (const foot::FootSpec& f : j.feet) {
    WalkerJob w = j.walker;
    w.foot = f;
    const JobCost c = walker_job_cost(w, "sweep", static_cast<int>(w.speeds.size()), static_cast<int>(j.sweeps.seed_speeds.size()));
    total.seconds += c.seconds;
    total.memory_bytes = std::max(total.memory_bytes, c.memory_bytes);
    total.field = c.field;
  }
  total.breakdown = std::to_string(j.feet.size()) + " speed sweeps (the reference and the feet) of " +
                    std::to_string(j.walker.speeds.size()) + " speeds";
  if (total.field.empty()) total.field = "feet";
  return total;
}

}  // namespace

JobKind foot_comparison_kind() {
  std::vector<std::string> fields;
  for (const std::string& f : walker_job_fields(true))
    if (f != "foot" && f != "start" && f != "free_parameters") fields.push_back(f);
  fields.insert(fields.end(), {"feet", "reference", "continuation"});
  return typed_job_kind<ComparisonJob>("foot_comparison", {"walker"}, fields, parse_comparison_job, run_comparison,
                                       comparison_job_json, comparison_cost);
}

}  // namespace cyclopt::service
