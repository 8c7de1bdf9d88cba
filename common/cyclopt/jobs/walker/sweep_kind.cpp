// Job kind "sweep" (scene walker): the chapter-9 workflow of seed 001 (studies/speed_sweep.hpp)
// over "speeds": multistarts ("multistart": starts, seed or seeds, scale) at the seed speeds,
// continuation of the best optima both ways and of every curve jumped to, recovery, the
// envelope's closure, the best point per speed. The walker fields of walker_job_spec.hpp and the
// "continuation" block of continuation_fields.hpp.
//
// Storage: curve c + 1 holds the sweep's solution curve c, its points stored the moment they exist
// (walker_points.hpp), named "solution curve c + 1": progress, recovery texts, query and plots
// number curves by curve_index; curve 0 the best point per speed once the sweep is done, each a walker
// point with a records::SweepBestRecord beside it (which step found it, or why none was found,
// and how sure it is). A resumed sweep replays what an earlier attempt finished from its journal
// (sweep_checkpoints.hpp).
#include "cyclopt/jobs/solver_progress.hpp"
#include "cyclopt/jobs/walker/continuation_fields.hpp"
#include "cyclopt/jobs/walker/job_sweep_observer.hpp"
#include "cyclopt/jobs/walker/walker_job_cost.hpp"
#include "cyclopt/jobs/walker/walker_job_json.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/jobs/walker/walker_kinds.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"
#include "cyclopt/records/sweep_records.hpp"
#include "cyclopt/studies/speed_sweep.hpp"
#include "cyclopt/studies/walker_family.hpp"

#include <cmath>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

struct SweepJob {
  WalkerJob walker;
  studies::SpeedSweepOptions sweep;  // the study's options, the job's observers not attached
};

SweepJob parse_sweep_job(const nlohmann::json& spec, const CommonJobFields& common) {
  SweepJob j;
  j.walker = parse_walker_job(spec, common, true);
  studies::SpeedSweepOptions& s = j.sweep;
  s.speeds = j.walker.speeds;
  s.starts = j.walker.starts;
  s.seeds = j.walker.seeds;
  s.scale = j.walker.scale;
  s.continuation.corrector = j.walker.solver;
  parse_sweep_continuation(spec, s);
  if (s.speeds.size() < 2) throw SpecError("speeds", "needs at least two values");
  return j;
}

// The resolved spec (resolved_spec.hpp): the walker fields with the multistart, the continuation block.
nlohmann::json sweep_job_json(const SweepJob& j) {
  nlohmann::json r = walker_job_json(j.walker, true, true);
  r["continuation"] = sweep_continuation_json(j.sweep);
  return r;
}

void run_sweep(const SweepJob& job, JobContext& ctx) {
  const walker::WalkerModel<double> model = job.walker.model();
  studies::SpeedSweepOptions so = job.sweep;
  PhaseProgress progress(ctx, {.points_total = static_cast<int>(so.speeds.size()), .message = "speed sweep"});
  so.continuation.corrector.on_iteration = progress.iterations();
  so.continuation.corrector.should_stop = stop_predicate(ctx);
  so.curve_label_offset = 1;  // texts name curves by their curve_index (CurveStore below)
  const continuation::ParametricProblem family = studies::walker_family(model, job.walker.problem, "speed");
  ctx.announce(static_cast<int>(so.speeds.size()));
  CurveStore store(ctx, family, 1, false);
  // A resumed sweep reuses what an earlier attempt finished (the job's journal).
  JobSweepObserver observer(
      ctx, [&](const continuation::CurvePoint& c) { return store(c); },
      [&](const studies::SweepProgress& p) { progress.set(sweep_progress_report(p, "speed sweep")); });
  const studies::SpeedSweepResult r = studies::speed_sweep(model, job.walker.problem, so, observer);
  if (ctx.stop_reason() != StopReason::none) return;
  ctx.add_curve(0, "best solution per speed", "speed");
  for (std::size_t i = 0; i < r.best.size(); ++i) {
    const studies::BestPoint& b = r.best[i];
    const storage::PointKey key{0, static_cast<int>(i)};
    WalkerPoint p;
    records::SweepBestRecord best;
    if (b.found) {
      p = store.point(b.point, key);  // required, as every best row
      best.found_by = studies::describe(b);  // which sweep step found the point
    } else {
      p.row.key = key;
      p.row.parameter = b.speed;
      p.row.status = "not found";
      best.reason = b.reason;
    }
    best.sweep_seconds = r.seconds;
    best.curves = r.curves;
    // How sure the point is: the closure's passes here, and the spread between the seeds' searches.
    best.closure = studies::describe(r.closure);
    best.closure_passes = b.closure_passes;
    if (std::isfinite(r.seed_spread[i])) best.seed_spread = r.seed_spread[i];
    // This attempt's work: what it solved and what it took over from earlier attempts.
    best.attempt = {r.multistart_solves, r.resumed_solves, r.computed_runs, r.resumed_runs};
    ctx.store_point(p.stored(best));
  }
}

}  // namespace

JobKind sweep_kind() {
  std::vector<std::string> fields = walker_job_fields(true);
  fields.push_back("continuation");
  return typed_job_kind<SweepJob>("sweep", {"walker"}, fields, parse_sweep_job, run_sweep, sweep_job_json,
                                  [](const SweepJob& j) {
                                    return walker_job_cost(j.walker, "sweep", static_cast<int>(j.sweep.speeds.size()),
                                                           static_cast<int>(j.sweep.seed_speeds.size()));
                                  });
}

}  // namespace cyclopt::jobs
