#pragma once
// The giant swing's job kind (scene and task "giant_swing", seed 000; the spec's fields in
// giant_swing_job_spec.hpp): one point per job, the motion solved by the seed's method or the
// Bezier minimum-jerk NLP (giant_swing_kind.cpp).
#include "cyclopt/service/job_kind.hpp"

namespace cyclopt::jobs {

service::JobKind giant_swing_kind();  // giant_swing_kind.cpp

}  // namespace cyclopt::jobs
