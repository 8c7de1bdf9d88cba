#include "cyclopt/service/solver_progress.hpp"

#include <utility>

namespace cyclopt::service {

IterationCallback solver_progress(JobContext& ctx, ProgressReport where) {
  return [&ctx, where = std::move(where)](const nlp::IterationReport& r) {
    ctx.count_iterations(1);
    ProgressReport report = where;
    report.iteration = r.iteration;
    report.objective = r.objective;
    report.constraint_violation = r.constraint_violation;
    ctx.report_progress(report);
    return ctx.stop_reason() == StopReason::none;
  };
}

IterationCallback stop_requests(JobContext& ctx) {
  return [&ctx](const nlp::IterationReport&) { return ctx.stop_reason() == StopReason::none; };
}

std::function<bool()> stop_predicate(JobContext& ctx) {
  return [&ctx] { return ctx.stop_reason() != StopReason::none; };
}

}  // namespace cyclopt::service
