#pragma once
// The one adapter from solver iterations to the running job, used by every job kind: each
// iteration counts towards the job's iteration limit, is reported as progress on top of what the
// kind says about the point being solved, and stops the solver as soon as the job should stop.

#include "cyclopt/nlp/solver_options.hpp"
#include "cyclopt/service/job_context.hpp"
#include "cyclopt/service/progress_report.hpp"
#include "cyclopt/studies/sweep_progress.hpp"

#include <functional>
#include <mutex>
#include <utility>

namespace cyclopt::jobs {

using IterationCallback = std::function<bool(const nlp::IterationReport&)>;

// For SolverOptions::on_iteration of a solve on the job's own thread. `where` describes the point
// (parameter, curve, points done/total, message); the callback fills in iteration, objective and
// constraint violation. The callback holds a reference to ctx.
IterationCallback solver_progress(service::JobContext& ctx, service::ProgressReport where);

// A job that goes through phases (a sweep's multistart batches, continuation runs, recoveries):
// set() replaces the phase and publishes it at once, iterations() reports every solver iteration
// on top of the current phase (job's own thread, as solver_progress). set() may be called from
// any thread; calls to ctx are serialised.
class PhaseProgress {
 public:
  PhaseProgress(service::JobContext& ctx, service::ProgressReport where) : ctx_(ctx), where_(std::move(where)) {}
  void set(const service::ProgressReport& where);
  IterationCallback iterations();

 private:
  service::JobContext& ctx_;
  std::mutex mutex_;
  service::ProgressReport where_;
};

// A speed sweep's progress (studies/sweep_progress.hpp) as the job's: points are the grid speeds
// reached, the phase and its ETA as the sweep measured them.
service::ProgressReport sweep_progress_report(const studies::SweepProgress& progress, std::string message);
// The phase without its ", curve c": for sweeps whose curves are not stored under the sweep's
// numbers (a foot comparison's feet, a foot design's sweeps), so progress names no curve that
// query and plots number otherwise.
std::string without_curve_number(std::string phase);

// For solves on other threads (nlp::multistart's workers), where JobContext's counting and
// reporting may not be called: only honours stop requests.
IterationCallback stop_requests(service::JobContext& ctx);

// For SolverOptions::should_stop of every solve of the job (polled before each evaluation, from
// any thread): cancel and the time limit then take effect within one evaluation.
std::function<bool()> stop_predicate(service::JobContext& ctx);

}  // namespace cyclopt::jobs
