#pragma once
// The job kinds this build of the server offers. New kinds add one line to the .cpp.

#include "cyclopt/service/job_kind.hpp"

namespace cyclopt::jobs {

service::JobKindRegistry builtin_job_kinds();

}  // namespace cyclopt::jobs
