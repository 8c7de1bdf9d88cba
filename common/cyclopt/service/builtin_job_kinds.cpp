#include "cyclopt/service/builtin_job_kinds.hpp"

#include "cyclopt/service/foot_sweep_kind.hpp"

namespace cyclopt::service {

JobKindRegistry builtin_job_kinds() {
  JobKindRegistry registry;
  registry.add(foot_sweep_kind());
  return registry;
}

}  // namespace cyclopt::service
