#pragma once
// The giant-swing job kind (scene and task "giant_swing", fields in giant_swing_job_spec.hpp): one
// point per job, the motion solved by the seed's method or the Bezier minimum-jerk NLP. The stored
// point's values: motion, method, rounds (end-of-round boundary values phi'/omega, alpha, alpha',
// friction, jerk, moment per completed round, full model), rounds_completed, integrations,
// wall_seconds, and for seed the support values of M_alpha (Nm), score and stages; for bezier the
// free coefficients (rad), the reduced-model values, the solver summary and, for periodic, the
// Floquet multipliers of the one-step map at the handstand.

#include "cyclopt/service/job_kind.hpp"

namespace cyclopt::jobs {

service::JobKind giant_swing_kind();

}  // namespace cyclopt::jobs
