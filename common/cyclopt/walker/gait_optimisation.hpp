#pragma once
// One call from a walker problem to an optimal gait: start (automatic starting gait, a given x, or
// a warm start), solve with the chosen NLP solver, and report the gait at the solution. (What the
// service stores of it: service/walker_records.hpp, the result contract of records/.)

#include "cyclopt/nlp/solver_options.hpp"
#include "cyclopt/walker/gait_problem.hpp"
#include "cyclopt/walker/starting_gait.hpp"

#include <optional>

namespace cyclopt::walker {

struct GaitOptimum {
  nlp::SolverSummary summary;
  Eigen::VectorXd z;                   // [x; free parameters] at the solution
  PeriodicGait<double> gait;           // evaluated at z, with trajectories
  WalkerModel<double> model;           // with the free parameters of z
  std::string start;                   // where the start came from
  double start_objective = 0.0;
};

// Appended to the summary's message of a feasible f_mech solve with the seed's positive part that
// ended without a KKT point.
inline constexpr const char* kUnsettledKinkHint =
    "; feasible but not a KKT point: if the gait holds a joint still, it sits at the kink of max(u q_dot, 0) (5.100), "
    "where the KKT test cannot settle - \"positive_power_band\": 1e-3 (W) rounds that kink";

// Solves from `start` (gait parameters x) or, if absent, from the automatic starting gait at
// options.speed. Throws std::runtime_error when no starting gait exists.
GaitOptimum optimise_gait(const WalkerModel<double>& model, const GaitProblemOptions& options,
                          const nlp::SolverOptions& solver, const std::optional<Eigen::VectorXd>& start = {});

}  // namespace cyclopt::walker
