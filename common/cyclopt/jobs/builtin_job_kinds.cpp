#include "cyclopt/jobs/builtin_job_kinds.hpp"

#include "cyclopt/jobs/foot/foot_kinds.hpp"
#include "cyclopt/jobs/giant_swing/giant_swing_kinds.hpp"
#include "cyclopt/jobs/walker/walker_kinds.hpp"

namespace cyclopt::jobs {

service::JobKindRegistry builtin_job_kinds() {
  service::JobKindRegistry registry;
  registry.add(foot_sweep_kind());
  registry.add(evaluate_kind());
  registry.add(optimise_kind());
  registry.add(multistart_kind());
  registry.add(continuation_kind());
  registry.add(sweep_kind());
  registry.add(sensitivity_kind());
  registry.add(foot_comparison_kind());
  registry.add(foot_design_kind());
  registry.add(foot_fit_kind());
  registry.add(giant_swing_kind());
  return registry;
}

}  // namespace cyclopt::jobs
