#include "cyclopt/service/builtin_job_kinds.hpp"

#include "cyclopt/service/foot_comparison_kind.hpp"
#include "cyclopt/service/foot_design_kind.hpp"
#include "cyclopt/service/foot_fit_kind.hpp"
#include "cyclopt/service/foot_sweep_kind.hpp"
#include "cyclopt/service/giant_swing_job_kind.hpp"
#include "cyclopt/service/walker_continuation_kinds.hpp"
#include "cyclopt/service/walker_job_kinds.hpp"
#include "cyclopt/service/walker_sensitivity_kind.hpp"

namespace cyclopt::service {

JobKindRegistry builtin_job_kinds() {
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

}  // namespace cyclopt::service
