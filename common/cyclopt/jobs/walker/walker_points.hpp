#pragma once
// Stored points of the walker job kinds: a gait (and the solve that produced it) as a
// storage::SolutionPoint whose values are a records::WalkerPointRecord (gait scalars, solver
// summary, start, continuation step, x) and whose trajectory is a records::GaitTrajectoryRecord.
#include "cyclopt/continuation/continuation_solver.hpp"
#include "cyclopt/records/sensitivity_records.hpp"
#include "cyclopt/storage/solution_point.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"
#include "cyclopt/walker/starting_gait.hpp"

namespace cyclopt::jobs {

// An evaluated gait and the start it was evaluated at.
storage::SolutionPoint point_of(const walker::PeriodicGait<double>& gait, const walker::GaitStart& start,
                                storage::PointKey key, double parameter);
// sensitivities: the optimum's KKT sensitivities (optimum_sensitivities.hpp), stored with it.
storage::SolutionPoint point_of(const walker::GaitOptimum& opt, storage::PointKey key, double parameter,
                                std::optional<records::KktSensitivitiesRecord> sensitivities = std::nullopt);
// A continuation point of the walker family `family` (studies::walker_family) with its gait and
// the continuation's own figures (curve id, predictor attempts, kappa, trust region, x).
storage::SolutionPoint point_of(const continuation::ParametricProblem& family, const continuation::CurvePoint& c,
                                storage::PointKey key);

}  // namespace cyclopt::jobs
