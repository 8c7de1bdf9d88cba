#pragma once
// What a continuation returns: the points it solved, each tagged with the id of the solution
// curve it lies on, and the jumps between curves it detected (reported, never hidden).
#include "cyclopt/nlp/solver_options.hpp"
#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace cyclopt::continuation {

struct CurvePoint {
  double parameter = 0.0;
  int curve_id = 0;
  bool on_grid = false;         // parameter is one of the requested values p_1..p_Q
  // The corrector succeeded (SolverSummary::success): a KKT point, or the SQP's "acceptable" stop (a
  // step below TolStep while feasible); corrector.termination tells which.
  bool converged = false;
  Eigen::VectorXd x;
  double objective = 0.0;
  nlp::SolverSummary corrector;  // the solve of Algorithm 2 step 19 (step 1 for the first point)
  int predictor_attempts = 0;    // QP-predictor tries (trust-region reductions + 1); 0 for trivial
  int predictor_steps = 0;       // SQP steps spent in the QP predictor (d_1, d_2 and retries)
  double kappa = std::numeric_limits<double>::quiet_NaN();  // eq. (7.2) of the accepted predictor
  double trust_region = 0.0;     // Delta_k when the step was taken
  double seconds = 0.0;          // predictor + corrector wall time of this point
};

struct CurveJump {
  int from_curve = 0, to_curve = 0;
  double from_parameter = 0.0, to_parameter = 0.0;
  double objective_before = 0.0, objective_after = 0.0;
  double relative_distance = 0.0;  // |x_after - x_before|_2 / max(1, |x_before|_2)
};

struct ContinuationResult {
  std::vector<CurvePoint> points;  // in the order solved
  std::vector<CurveJump> jumps;
  bool finished = false;           // reached the last requested value
  std::string message;             // why it stopped
  int next_curve_id = 0;           // first id not used by this run
  int corrector_iterations = 0;    // sum over points
  int predictor_steps = 0;
  double seconds = 0.0;
};

// Where a run stands after a converged point (the last of result.points): everything Algorithm 2
// carries to its next step, so that continue_solution resumed from it computes the same steps, bit
// for bit, as the run that was not interrupted (a run resumed after a crash, studies/sweep_journal.hpp).
struct RunState {
  ContinuationResult result;     // so far; result.next_curve_id: the id the next jump gets
  int curve_id = 0;              // of the last point
  std::size_t next_value = 1;    // l: the requested value p_l the run steps towards
  std::size_t tried_value = 0;   // Predictor::trivial_then_qp: the last value whose direct step was tried
  std::optional<double> secant;  // of the last step on the current curve
  double trust_region = 0.0;     // Delta_k for the next step
};

// Gives the curves `run` jumped to - numbered from `from` on, its CurveStart::next_curve_id - the
// ids from `to` on: for a run computed before the id of its first new curve was known (a sweep's
// downward run computed beside the upward one, studies/speed_sweep.cpp). Ids below `from` stay.
inline void renumber_new_curves(ContinuationResult& run, int from, int to) {
  const auto renumber = [from, to](int& id) {
    if (id >= from) id = to + (id - from);
  };
  for (CurvePoint& p : run.points) renumber(p.curve_id);
  for (CurveJump& j : run.jumps) {
    renumber(j.from_curve);
    renumber(j.to_curve);
  }
  renumber(run.next_curve_id);
}

inline void renumber_new_curves(RunState& state, int from, int to) {
  renumber_new_curves(state.result, from, to);
  if (state.curve_id >= from) state.curve_id = to + (state.curve_id - from);
}

}  // namespace cyclopt::continuation
