// Job kind "foot_comparison" (scene walker; issue 16 item 5, seed 001 section 9.2): one chapter-9
// speed sweep per foot, the best foot per speed and each foot's mean f_mech and saving against
// the reference feet (studies/foot_comparison.hpp).
//
//   {"scene": "walker", "task": "foot_comparison", "speeds": "0.3:0.1:2.3",
//    "feet": ["P1-shoes-left-HM-SG", "P2-shoes-left-HMT-SG", {"model": "HM", ...}],
//    "reference": "point", "multistart": {"starts": 20}}
//
// feet: preset names or foot specs (default: the 16 feet of section 9.2); reference: the foot
// savings are measured against (default "point", Table D.1), swept first; the other walker
// fields as for a sweep (speeds, points, bezier_degree, quadrature, objective, solver,
// multistart, continuation.seed_speeds / min_trust_region) apply to every foot; "foot", "start"
// and "free_parameters" are not fields of it.
//
// Stored curves: 0 the best foot per speed (its point, values.foot, values.saving); 1 the
// reference; 2 .. F+1 the feet in the given order, each the best point of its sweep per speed
// (values.found_by, or status "not found" with values.reason); F+2 one point per foot (parameter:
// its curve index) with values.foot, mean_f_mech, common_speeds, speeds_found, saving,
// best_fitted, sweep_seconds.
#include "cyclopt/foot/fitted_feet.hpp"
#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/jobs/foot/foot_kinds.hpp"
#include "cyclopt/jobs/solver_progress.hpp"
#include "cyclopt/jobs/walker/continuation_fields.hpp"
#include "cyclopt/jobs/walker/job_sweep_observer.hpp"
#include "cyclopt/jobs/walker/foot_sweep_points.hpp"
#include "cyclopt/jobs/walker/sweep_checkpoints.hpp"
#include "cyclopt/jobs/walker/walker_job_cost.hpp"
#include "cyclopt/jobs/walker/walker_job_json.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/records/foot_comparison_records.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/service/unit_job_context.hpp"
#include "cyclopt/studies/foot_comparison.hpp"
#include "cyclopt/studies/walker_family.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

struct ComparisonJob {
  WalkerJob walker;                       // the common fields; walker.foot is the reference
  std::vector<foot::FootSpec> feet;       // the reference first, then the compared feet
  studies::SpeedSweepOptions sweep;       // every foot's, the job's observers not attached
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
      j.feet.push_back(named(io::foot_value(f[i], path), f[i], path));
    }
  } else {  // seed 001 section 9.2
    for (const foot::FittedFoot* f : foot::select_fitted_feet({.section_9_2_only = true})) {
      j.feet.push_back(f->spec);
      j.feet.back().name = f->name();
    }
  }
  j.sweep.speeds = j.walker.speeds;
  j.sweep.starts = j.walker.starts;
  j.sweep.seeds = j.walker.seeds;
  j.sweep.scale = j.walker.scale;
  j.sweep.continuation.corrector = j.walker.solver;
  parse_sweep_continuation(spec, j.sweep);
  std::set<std::string> seen;
  for (std::size_t i = 0; i < j.feet.size(); ++i)
    if (!seen.insert(j.feet[i].name).second)
      throw SpecError(i == 0 ? "reference" : "feet[" + std::to_string(i - 1) + "]",
                      "foot '" + j.feet[i].name + "' is compared twice");
  return j;
}

// Each foot's sweep is a work unit "foot-<k>" (issue 18; k = 0 the reference): it stores the
// foot's best point per speed as curve 1 + k as soon as its sweep ends, then its summary as the
// unit's checkpoint kSweptFootCheckpoint, which the job reads to compare the feet. Within a unit
// the sweep keeps its journal (sweep_checkpoints.hpp), so an interrupted unit resumes where it was.
std::string foot_unit_id(std::size_t k) { return "foot-" + std::to_string(k); }

// How many of the job's `feet` are swept: their best points (curves 1..feet) are stored.
int feet_swept(JobContext& ctx, int feet) {
  std::set<int> curves;
  for (const storage::PointKey& key : ctx.already_stored_points())
    if (key.curve_index >= 1 && key.curve_index <= feet) curves.insert(key.curve_index);
  return static_cast<int>(curves.size());
}
// A unit's progress reports recount the swept feet at most this often (a query of the store).
constexpr std::chrono::seconds kFeetSweptRecount{2};

void run_foot(const ComparisonJob& job, const WorkUnit& unit, JobContext& ctx) {
  if (ctx.stored_checkpoints().count(kSweptFootCheckpoint)) return;  // swept by an earlier attempt
  if (unit.index < 0 || static_cast<std::size_t>(unit.index) >= job.feet.size())
    throw std::logic_error("foot_comparison: no foot " + std::to_string(unit.index) + " in the job");
  const std::size_t k = static_cast<std::size_t>(unit.index);
  const int feet = static_cast<int>(job.feet.size());
  const int speeds = static_cast<int>(job.walker.speeds.size());
  WalkerJob w = job.walker;
  w.foot = job.feet[k];
  const walker::WalkerModel<double> model = w.model();
  studies::SpeedSweepOptions o = job.sweep;
  o.continuation.corrector.should_stop = stop_predicate(ctx);
  // Progress names the foot and the phase of its sweep. Points count the grid speeds of the feet
  // already swept (their best points are stored, whichever unit swept them: units may run at
  // once) and of this foot; the ETA is this foot's sweep's: the server adds the feet not begun
  // (service/progress_meter.hpp), knowing how many units run at once.
  auto counted = std::chrono::steady_clock::now() - kFeetSweptRecount;
  int swept = 0;
  PhaseProgress progress(ctx, {.curve_id = 1 + unit.index, .points_total = feet * speeds});
  o.continuation.corrector.on_iteration = progress.iterations();
  const auto report = [&](const studies::SweepProgress& sp) {  // one call at a time (speed_sweep.hpp)
    if (const auto now = std::chrono::steady_clock::now(); now - counted >= kFeetSweptRecount) {
      swept = feet_swept(ctx, feet);
      counted = now;
    }
    ProgressReport r = sweep_progress_report(sp, "foot " + std::to_string(k + 1) + "/" + std::to_string(feet) + " " +
                                                     job.feet[k].name);
    r.curve_id = 1 + unit.index;
    r.phase = r.message + ": " + without_curve_number(r.phase);  // a phase change names its foot
    r.points_done = swept * speeds + sp.speeds_reached;
    r.points_total = feet * speeds;
    progress.set(r);
  };
  JobSweepObserver observer(
      ctx, [&](const studies::CurvePoint&) { return ctx.stop_reason() == StopReason::none; }, report);
  const studies::FootSweepSummary s = studies::sweep_foot(job.feet[k].name, model, job.walker.problem, o, observer);
  if (s.stopped || ctx.stop_reason() != StopReason::none) return;  // the next attempt resumes from the journal
  const studies::ParametricProblem family = studies::walker_family(model, job.walker.problem, "speed");
  for (const ComparedSpeedPoint& p : best_points(family, s, 1 + unit.index)) ctx.store_point(p.stored());
  ctx.store_checkpoint(kSweptFootCheckpoint, foot_sweep_to_json(s).dump());
}

void run_comparison(const ComparisonJob& job, JobContext& ctx) {
  const int feet = static_cast<int>(job.feet.size());
  const int speeds = static_cast<int>(job.walker.speeds.size());
  ctx.announce(feet * speeds + speeds + feet);
  ctx.add_curve(0, "best foot per speed", "speed");
  for (int k = 0; k < feet; ++k)
    ctx.add_curve(1 + k, "foot " + job.feet[static_cast<std::size_t>(k)].name + (k == 0 ? " (reference)" : ""), "speed");
  ctx.add_curve(feet + 1, "mean f_mech per foot", "curve");
  const auto started = std::chrono::steady_clock::now();
  std::vector<WorkUnit> units;
  for (int k = 0; k < feet; ++k) units.push_back({foot_unit_id(static_cast<std::size_t>(k)), k});
  ctx.run_units(units, [&job](const WorkUnit& unit, JobContext& c) { run_foot(job, unit, c); });
  if (ctx.stop_reason() != StopReason::none) return;
  const std::map<std::string, std::string> stored = ctx.stored_checkpoints();
  std::vector<studies::FootSweepSummary> swept;
  for (const WorkUnit& unit : units)
    swept.push_back(unit_result(stored, unit, kSweptFootCheckpoint, [](const nlohmann::json& j) { return foot_sweep_from_json(j); }));
  const studies::FootComparisonResult r = studies::summarise_feet(job.walker.speeds, std::move(swept), 0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::map<int, std::vector<ComparedSpeedPoint>> best_of;  // curve 1 + k's points, of the feet best somewhere
  for (int i = 0; i < speeds; ++i) {
    const int best = r.best_foot[static_cast<std::size_t>(i)];
    const double ref = r.feet[0].f_mech[static_cast<std::size_t>(i)];
    ComparedSpeedPoint p;
    records::ComparedSpeedRecord& c = p.speed;
    if (best < 0) {
      p.point.row.key = {0, i};
      p.point.row.parameter = job.walker.speeds[static_cast<std::size_t>(i)];
      p.point.row.status = "not found";
      c.reason = "no compared foot has a point at this speed";
    } else {
      if (!best_of.count(best)) {
        WalkerJob w = job.walker;
        w.foot = job.feet[static_cast<std::size_t>(best)];
        best_of[best] = best_points(studies::walker_family(w.model(), job.walker.problem, "speed"),
                                    r.feet[static_cast<std::size_t>(best)], 1 + best);
      }
      p = best_of[best][static_cast<std::size_t>(i)];
      p.point.row.key = {0, i};
      if (std::isfinite(ref) && ref > 0.0) c.saving = 1.0 - r.envelope_f_mech[static_cast<std::size_t>(i)] / ref;
    }
    c.reference_f_mech = ref;
    if (best >= 0) {  // the spread of the best foot's own searches at this speed
      const studies::FootSweepSummary& s = r.feet[static_cast<std::size_t>(best)];
      std::vector<double> at_speed;
      for (const std::vector<double>& f : s.seed_f_mech) at_speed.push_back(f.at(static_cast<std::size_t>(i)));
      const double width = studies::spread(at_speed);  // NaN unless every search has a point here
      const double lo = *std::min_element(at_speed.begin(), at_speed.end());
      if (std::isfinite(width) && lo > 0.0) c.seed_spread = width / lo;
    }
    ctx.store_point(p.stored());
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
    if (s.seed_savings.size() > 1) f.seed_savings = s.seed_savings;
    if (s.rank >= 0) f.rank = s.rank;
    f.order_held = s.order_held;
    f.foot_spec = io::to_json(job.feet[static_cast<std::size_t>(k)]);
    if (k == 0) {
      f.envelope_saving = r.envelope_saving;
      f.envelope_common_speeds = r.envelope_common_speeds;
      f.comparison_seconds = seconds;
    }
    p.set_values(f);
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
  r["continuation"] = sweep_continuation_json(j.sweep);
  return r;
}

// One speed sweep per foot, one after the other.
JobCost comparison_cost(const ComparisonJob& j) {
  JobCost total;
  for (const foot::FootSpec& f : j.feet) {
    WalkerJob w = j.walker;
    w.foot = f;
    const JobCost c = walker_job_cost(w, "sweep", static_cast<int>(w.speeds.size()), static_cast<int>(j.sweep.seed_speeds.size()));
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
  return with_work_units<ComparisonJob>(typed_job_kind<ComparisonJob>("foot_comparison", {"walker"}, fields,
                                                                      parse_comparison_job, run_comparison,
                                                                      comparison_job_json, comparison_cost),
                                        run_foot);
}

}  // namespace cyclopt::jobs
