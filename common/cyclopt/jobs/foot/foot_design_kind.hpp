#pragma once
// Job kind "foot_design" (scene walker; issue 15 item 3, seed 001 section 10.2): the foot-geometry
// optimisation of studies/foot_design.hpp as a job. Per density of a list, a multistart at the
// design speed with foot and gait free from the start foot, the best admissible design, its
// free-foot continuation over the speeds (an optimal foot per speed, Fig. 10.2a), the fixed-foot
// sweeps of the designs optimal at the highest and the lowest speed, and their savings against
// the start foot and point feet.
//
//   {"scene": "walker", "task": "foot_design", "foot": "P2-shoes-left-HMT", "speeds": "0.3:0.1:2.3",
//    "densities": "10:10:70", "design_speed": 2.3, "multistart": {"starts": 20}, "sweep_starts": 20}
//
// foot: the start foot, HM or HMT (default P2-shoes-left-HMT), also the start-foot reference with
// its own masses; densities (kg/m^2, default 10:10:70); design_speed (m/s, one of the speeds,
// default 2.3); speeds (default 0.3:0.1:2.3); multistart: starts (default 20), seed and scale of
// the design multistart, seed and scale of the sweeps too; sweep_starts: multistart runs per seed
// speed of every fixed-foot sweep (default 20); foot_scale: the spread of the feet the design
// starts draw around the start foot (studies::FootDesignOptions::foot_scale, default 1, 0: none);
// free_parameters: the foot parameters designed
// (default all of the model's; only foot parameters); design_bounds: (10.1) (design_bounds_spec.hpp,
// default the seed's); references: sweep the start foot and point feet (default true; false: no
// savings); continuation: seed_speeds and min_trust_region of the sweeps and the continuation;
// points, bezier_degree, quadrature, objective, solver as for a sweep. Bad densities, bounds that
// exclude the start foot in a fixed parameter, a parameter the foot model does not have and a
// design speed off the grid are refused at submission, naming the field.
//
// Stored (records/foot_design_records.hpp): curve 0 one point per density (a DesignedFootRecord;
// status "no admissible design" where the multistart found none), curves 1, 2 the best point per
// speed of the start foot and point feet, per density k: curve 3 + 4k the multistart's optima
// (every class kept), 4 + 4k the free-foot continuation's points, 5 + 4k and 6 + 4k the best point
// per speed of the fixed-foot sweeps of the high- and low-speed designs. Each is stored when its
// phase ends; a resumed job replays the finished solves and runs from its checkpoints
// (sweep_checkpoints.hpp) instead of solving them again.
#include "cyclopt/service/job_kind.hpp"

namespace cyclopt::jobs {

service::JobKind foot_design_kind();

}  // namespace cyclopt::jobs
