#include "cyclopt/jobs/builtin_job_kinds.hpp"

#include "cyclopt/jobs/foot/foot_comparison_kind.hpp"
#include "cyclopt/jobs/foot/foot_design_kind.hpp"
#include "cyclopt/jobs/foot/foot_fit_kind.hpp"
#include "cyclopt/jobs/foot/foot_sweep_kind.hpp"
#include "cyclopt/jobs/giant_swing/giant_swing_kind.hpp"
#include "cyclopt/jobs/walker/walker_continuation_kinds.hpp"
#include "cyclopt/jobs/walker/walker_job_kinds.hpp"
#include "cyclopt/jobs/walker/sensitivity_kind.hpp"

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

service::JobKindRegistry builtin_job_kinds() {
  JobKindRegistry registry;
  registry.add(foot_sweep_kind());
  registry.add(walker_evaluate_kind());
  registry.add(walker_optimise_kind());
  registry.add(walker_multistart_kind());
  registry.add(walker_continuation_kind());
  registry.add(walker_sweep_kind());
  registry.add(walker_sensitivity_kind());
  registry.add(foot_comparison_kind());
  registry.add(foot_design_kind());
  registry.add(foot_fit_kind());
  registry.add(giant_swing_kind());
  return registry;
}

}  // namespace cyclopt::jobs
