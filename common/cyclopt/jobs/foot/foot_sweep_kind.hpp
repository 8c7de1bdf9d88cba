#pragma once
// Built-in job kind "foot_sweep" (scene walker): the foot's mass properties (seed 001,
// appendix E) and its rolling kinematics over a grid of one foot parameter. Cheap, so the whole
// service can be exercised end-to-end before the walker optimisation kinds exist.
//
//   {"scene": "walker", "task": "foot_sweep",
//    "foot": "P2-shoes-left-HMT" | {foot spec, proto/schemas/foot.schema.json},
//    "sweep": {"parameter": "density" | a parameter of the foot model (e.g. "k_HM"),
//              "values": "lo:step:hi" | number | [numbers]},
//    "samples": 2..200 rolling-kinematics samples stored as each point's trajectory (default 13),
//    "point_delay_ms": 0..10000 extra wall time per point (default 0; for resume tests)}
//
// Every grid value must give a valid foot (checked by validate()); without a density in the
// foot, 36.9 kg/m^2 is used (seed 001, section 10.2). Each point (curve 0, point i) stores
// values = {area, mass, com_x, com_z, inertia_ankle, inertia_com, com_distance, theta_F0,
// theta_min, theta_max}, objective = mass (kg), and the rolling samples as its trajectory.

#include "cyclopt/service/job_kind.hpp"

namespace cyclopt::jobs {

inline constexpr double kDefaultFootDensity = 36.9;  // kg/m^2
inline constexpr int kMaxPointDelayMs = 10000;

service::JobKind foot_sweep_kind();

}  // namespace cyclopt::jobs
