#pragma once
// Plain option and summary structs shared by every NLP solver (Ipopt adapter, the seed's SQP),
// in the style of Ceres' Solver::Options / Solver::Summary.

#include "cyclopt/nlp/ipopt_options.hpp"
#include "cyclopt/nlp/sqp_options.hpp"

#include <Eigen/Core>

#include <functional>
#include <limits>
#include <string>

namespace cyclopt::nlp {

enum class SolverKind { ipopt, sqp };

const char* to_string(SolverKind kind);
// "ipopt" or "sqp"; anything else throws std::invalid_argument naming `field` and the allowed values.
SolverKind parse_solver_kind(const std::string& text, const std::string& field = "solver");

// One line of progress, handed to SolverOptions::on_iteration after every iteration.
struct IterationReport {
  int iteration = 0;
  double objective = 0.0;
  double constraint_violation = 0.0;  // max(|c_eq|, max(c_in, 0), bound violation)
  double kkt_error = 0.0;             // solver's own optimality measure
  double step_norm = 0.0;
  double wall_seconds = 0.0;
};

struct SolverOptions {
  SolverKind solver = SolverKind::ipopt;
  int max_iterations = 500;
  double optimality_tolerance = 1e-8;  // KKT (dual infeasibility) tolerance
  double constraint_tolerance = 1e-8;  // max constraint violation at termination
  double max_wall_seconds = std::numeric_limits<double>::infinity();
  int print_level = 0;  // 0 = silent
  // Called after every iteration; returning false stops the solver (termination = user_stop).
  std::function<bool(const IterationReport&)> on_iteration;
  // Polled before every problem evaluation (and by multistart before every start, by
  // continuation before every predictor): returning true ends the solve with user_stop within
  // one evaluation. Must be cheap and thread-safe (multistart calls it from its threads).
  std::function<bool()> should_stop;
  IpoptOptions ipopt;  // used when solver == ipopt
  SqpOptions sqp;      // used when solver == sqp
};

// Throws std::invalid_argument naming the first field outside its admissible range.
void validate(const SolverOptions& options);

// The seed's SQP exactly as Table 6.2 parameterises it: TolOpt = 1e-5, TolCon = 1e-10,
// MaxIter = 2000, MaxTime = infinity, and the SqpOptions defaults.
SolverOptions seed_table_6_2_options();

enum class Termination {
  converged,            // KKT point within tolerances
  acceptable,           // solver's "acceptable" point (looser tolerances)
  max_iterations,
  time_limit,
  infeasible,           // locally infeasible / restoration failed
  evaluation_failure,   // could not evaluate at (or near) the start point
  user_stop,
  numerical_failure,
  stalled,              // no progress over SqpOptions::progress_window iterations (the last value)
};

const char* to_string(Termination t);

// Which optimality test a converged point passed: the KKT test, or the nonsmooth (Clarke) test
// of issue 52 (SqpOptions::kinks; clarke_stationarity.hpp) at a point on kinks of the objective.
enum class Optimality { none, kkt, nonsmooth_kkt };

const char* to_string(Optimality o);  // "none", "KKT", "nonsmooth KKT"

struct SolverSummary {
  Termination termination = Termination::numerical_failure;
  std::string message;          // solver-specific explanation
  int iterations = 0;
  int function_evaluations = 0;  // evaluations without derivatives
  int jacobian_evaluations = 0;  // evaluations with derivatives
  int failed_evaluations = 0;    // evaluations that returned !ok
  int qp_iterations = 0;         // SQP: active-set iterations of all its QP subproblems (Ipopt: 0)
  double wall_seconds = 0.0;
  double objective = 0.0;
  double kkt_error = 0.0;
  double constraint_violation = 0.0;
  Eigen::VectorXd x;                      // final point
  Eigen::VectorXd equality_multipliers;   // Lagrange multipliers at x
  Eigen::VectorXd inequality_multipliers;
  Eigen::VectorXd bound_multipliers;      // nu: > 0 at an active upper bound, < 0 at an active lower bound
  Optimality optimality = Optimality::none;  // of a converged run; none otherwise
  // With nonsmooth_kkt: sigma_s in [0, w_s] per sample of Evaluation::kinks at x (0 off the kinks the
  // test used); empty otherwise.
  Eigen::VectorXd kink_multipliers;
  // Sign convention (both solvers): at a KKT point
  //   grad f + J_eq' equality_multipliers + J_in' inequality_multipliers + bound_multipliers = 0,
  // inequality_multipliers >= 0 (c_in <= 0); kkt_error is the infinity norm of the left side. At a
  // nonsmooth KKT point the left side has + sum_s (kink_multipliers_s - a_s) grad p_s
  // (kkt_measures.hpp's kinked Lagrangian gradient).
  bool success() const { return termination == Termination::converged || termination == Termination::acceptable; }
};

// Which runs a caller takes as solved. "acceptable" is the SQP's stop at a step below TolStep while
// feasible (Algorithm 1 step 3: a *potential* KKT point) or Ipopt's acceptable level; kkt_only
// takes converged runs alone (a design the study builds on: rho 30 and 50 of
// bench/results/foot_design_bench.txt chose "acceptable" designs that no continuation could follow).
enum class Acceptance { kkt_or_acceptable, kkt_only };
inline bool accepted(const SolverSummary& run, Acceptance a) {
  return a == Acceptance::kkt_only ? run.termination == Termination::converged : run.success();
}

}  // namespace cyclopt::nlp
