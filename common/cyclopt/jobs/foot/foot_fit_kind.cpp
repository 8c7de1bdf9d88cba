// Job kind "foot_fit" (scene walker): the seed's three steps of fitting a rolling foot
// to measured ankle trajectories (seed 001 section 4.2: circle-fit start 4.9-4.12, HM fit
// 4.13-4.17, HMT fit 4.18-4.22 from it), as `cyclopt-foot fit` runs them.
//
//   {"scene": "walker", "task": "foot_fit",
//    "trials": [{"source": "trial1.trc", "x": [m, ...], "z": [m, ...]}, ...],
//    "toe_bound": true | false (default true: the seed's l_MT <= z_min, eq. 4.18b)}
//
// The trials are the sagittal ankle tracks of the rolling phase inline (io/foot_fit_json.hpp;
// `cyclopt-foot fit --job-spec FILE TRIALS...` and `cyclopt submit --task foot_fit --trials
// A,B,...` read .trc / CSV files, naming file, line and column of a malformed one, and write
// them), so a spec of at most 16 KiB (channels::kMaxSpecBytes) carries about 1000 samples. A
// trial the circle-fit start cannot use is rejected at submission under "trials".
//
// Stored (curve 0): point 0 the HM fit, point 1 the HMT fit, each a records::FootFitRecord
// (parameters with bounds and standard errors, RMS / max residual, residual per trial, convexity
// check, the fitted foot spec); parameter 0 / 1, objective the RMS residual (m), status
// converged or the solver's reason; its trajectory the fitted foot angles per trial and sample
// (records::FootFitAnglesRecord). A walker job uses a stored fit as its foot by reference,
// "foot": {"fit": {"job": J, "model": "HMT"}} (stored_foot_fit.hpp).
#include "cyclopt/foot_fit/circle_fit_start.hpp"
#include "cyclopt/foot_fit/rolling_foot_fit.hpp"
#include "cyclopt/io/foot_fit_json.hpp"
#include "cyclopt/jobs/foot/foot_kinds.hpp"

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

struct FootFitJob {
  std::vector<foot_fit::AnkleTrack> tracks;
  bool toe_bound = true;
};

FootFitJob parse(const nlohmann::json& spec, const CommonJobFields&) {
  FootFitJob job;
  if (!spec.contains("trials"))
    throw SpecError("trials", "is required: the ankle tracks [{\"source\": ..., \"x\": [m], \"z\": [m]}, ...]");
  job.tracks = io::ankle_tracks_from_json(spec["trials"], "trials");
  if (spec.contains("toe_bound")) {
    if (!spec["toe_bound"].is_boolean()) throw SpecError("toe_bound", "must be true or false");
    job.toe_bound = spec["toe_bound"].get<bool>();
  }
  try {
    foot_fit::circle_fit_start(job.tracks);  // cheap: a trial that cannot start the fit is rejected now
  } catch (const std::invalid_argument& e) {
    throw SpecError("trials", e.what());
  }
  return job;
}

storage::SolutionPoint fit_point(int index, const foot_fit::FootFitResult& fit) {
  storage::SolutionPoint p;
  p.key = {0, index};
  p.parameter = index;
  p.objective = fit.rms;
  p.iterations = fit.iterations;
  p.status = fit.converged ? "converged" : "not converged";  // the reason: values.message
  p.set_values(io::foot_fit_record(fit));
  p.set_trajectory(io::foot_fit_angles_record(fit));  // for the figures of the stored fit (Fig. 4.3a)
  return p;
}

void run(const FootFitJob& job, JobContext& ctx) {
  ctx.announce(2);
  ctx.add_curve(0, "foot fit: HM, HMT (seed 001 section 4.2)", "model (0 HM, 1 HMT)");
  const std::set<storage::PointKey> done = ctx.already_stored_points();
  if (done.count({0, 0}) && done.count({0, 1})) return;
  foot_fit::FootFitOptions options;
  options.toe_bound = job.toe_bound;
  const foot_fit::CircleFitStart start = foot_fit::circle_fit_start(job.tracks);
  // The HMT fit starts from the HM result, so a resumed job without its HMT point fits HM again.
  const foot_fit::FootFitResult hm = foot_fit::fit_hm(job.tracks, start, options);
  ctx.count_iterations(hm.iterations);
  if (!done.count({0, 0})) ctx.store_point(fit_point(0, hm));
  ctx.report_progress({.iteration = hm.iterations, .objective = hm.rms, .points_done = 1, .points_total = 2,
                       .message = "HM fit done, HMT fit"});
  if (ctx.stop_reason() != StopReason::none) return;
  const foot_fit::FootFitResult hmt = foot_fit::fit_hmt(job.tracks, hm, start.z_min, options);
  ctx.count_iterations(hmt.iterations);
  ctx.store_point(fit_point(1, hmt));
  ctx.report_progress({.iteration = hm.iterations + hmt.iterations, .objective = hmt.rms, .points_done = 2,
                       .points_total = 2, .message = "HMT fit done"});
}

nlohmann::json resolve(const FootFitJob& job) {
  return {{"trials", io::to_json(job.tracks)}, {"toe_bound", job.toe_bound}};
}

}  // namespace

JobKind foot_fit_kind() {
  // No estimate: a spec of at most 16 KiB holds ~1000 samples, fitted in seconds.
  return typed_job_kind<FootFitJob>("foot_fit", {"walker"}, {"trials", "toe_bound"}, parse, run, resolve);
}

}  // namespace cyclopt::jobs
