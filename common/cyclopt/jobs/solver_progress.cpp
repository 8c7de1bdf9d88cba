#include "cyclopt/jobs/solver_progress.hpp"

#include <utility>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

// `where` with the solver's iteration on top.
ProgressReport at_iteration(ProgressReport where, const nlp::IterationReport& r) {
  where.iteration = r.iteration;
  where.objective = r.objective;
  where.constraint_violation = r.constraint_violation;
  return where;
}

}  // namespace

IterationCallback solver_progress(JobContext& ctx, ProgressReport where) {
  return [&ctx, where = std::move(where)](const nlp::IterationReport& r) {
    ctx.count_iterations(1);
    ctx.report_progress(at_iteration(where, r));
    return ctx.stop_reason() == StopReason::none;
  };
}

void PhaseProgress::set(const ProgressReport& where) {
  const std::lock_guard lock(mutex_);
  where_ = where;
  ctx_.report_progress(where_);
}

IterationCallback PhaseProgress::iterations() {
  return [this](const nlp::IterationReport& r) {
    ctx_.count_iterations(1);
    {
      const std::lock_guard lock(mutex_);
      ctx_.report_progress(at_iteration(where_, r));
    }
    return ctx_.stop_reason() == StopReason::none;
  };
}

ProgressReport sweep_progress_report(const studies::SweepProgress& p, std::string message) {
  ProgressReport r;
  r.points_done = p.speeds_reached;
  r.points_total = p.speeds_total;
  r.message = std::move(message);
  r.phase = std::string(studies::to_string(p.phase)) + " " + p.detail;
  r.phase_done = p.phase_done;
  r.phase_total = p.phase_total;
  r.best_objective = p.best_objective;
  r.eta_seconds = p.eta_seconds;
  return r;
}

std::string without_curve_number(std::string phase) {
  if (const std::size_t c = phase.rfind(", curve "); c != std::string::npos) phase.erase(c);
  return phase;
}

IterationCallback stop_requests(JobContext& ctx) {
  return [&ctx](const nlp::IterationReport&) { return ctx.stop_reason() == StopReason::none; };
}

std::function<bool()> stop_predicate(JobContext& ctx) {
  return [&ctx] { return ctx.stop_reason() != StopReason::none; };
}

}  // namespace cyclopt::jobs
