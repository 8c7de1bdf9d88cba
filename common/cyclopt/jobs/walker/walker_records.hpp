#pragma once
// The walker's numerical results as records of the result contract (records/): what the walker
// job kinds store (walker_points.hpp) and nothing else. Seed 001 ch. 5.
#include "cyclopt/continuation/solution_curve.hpp"
#include "cyclopt/nlp/solver_options.hpp"
#include "cyclopt/records/gait_records.hpp"
#include "cyclopt/records/sensitivity_records.hpp"
#include "cyclopt/records/solver_record.hpp"
#include "cyclopt/records/walker_point_record.hpp"
#include "cyclopt/studies/optimum_sensitivities.hpp"
#include "cyclopt/walker/periodic_gait.hpp"

namespace cyclopt::jobs {

records::GaitRecord gait_record(const walker::PeriodicGait<double>& gait);
// nullopt when the gait carries no trajectory (it was not reconstructed on the grid).
std::optional<records::GaitTrajectoryRecord> trajectory_record(const walker::GaitTrajectory<double>& trajectory);
records::SolverRecord solver_record(const nlp::SolverSummary& summary);
// Where a continuation point lies on its curve and how the step to it went (Algorithm 2).
records::ContinuationStepRecord continuation_step_record(const continuation::CurvePoint& point);
// nullopt where the study computed none (the optimum did not converge).
std::optional<records::KktSensitivitiesRecord> sensitivities_record(const std::optional<studies::OptimumSensitivities>& s);

}  // namespace cyclopt::jobs
