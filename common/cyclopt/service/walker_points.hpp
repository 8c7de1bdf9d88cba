#pragma once
// Stored points of the walker job kinds: a gait (and the solve that produced it) as a
// storage::SolutionPoint with the gait scalars, solver summary and x in `values` and the
// trajectories on the phase grid.
#include "cyclopt/continuation/continuation_solver.hpp"
#include "cyclopt/storage/solution_point.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"

namespace cyclopt::service {

storage::SolutionPoint point_of(const walker::PeriodicGait<double>& gait, storage::PointKey key, double parameter);
storage::SolutionPoint point_of(const walker::GaitOptimum& opt, storage::PointKey key, double parameter);
// A continuation point of the walker family `family` (studies::walker_family) with its gait and
// the continuation's own figures (curve id, predictor attempts, kappa, trust region, x).
storage::SolutionPoint point_of(const continuation::ParametricProblem& family, const continuation::CurvePoint& c,
                                storage::PointKey key);

}  // namespace cyclopt::service
