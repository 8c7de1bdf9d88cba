#pragma once
// Multistart: N local solves from sampled starts, in parallel, reproducibly.
//
// Start i draws its x0 from a std::mt19937_64 seeded with base_seed + i, so the starts - and,
// since every solve is deterministic, the results and their ranking - do not depend on the
// number of threads. Each thread builds its own Problem from the factory (problems hold
// workspace and are not shared between threads). Once solver.should_stop says stop, no further
// start is sampled or begun (those runs end as user_stop) and the running solves stop within one
// evaluation.

#include "cyclopt/nlp/problem.hpp"
#include "cyclopt/nlp/solver_options.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <vector>

namespace cyclopt::nlp {

struct MultistartOptions {
  int num_starts = 20;            // N; >= 1
  std::uint64_t base_seed = 0;    // start i uses seed base_seed + i
  int num_threads = 0;            // 0: std::thread::hardware_concurrency(); else >= 1
  // Two successful runs are the same optimum if |f_a - f_b| <= objective_tolerance * max(1, |f_a|)
  // and |x_a - x_b|_inf <= x_tolerance * max(1, |x_a|_inf). Both >= 0.
  double objective_tolerance = 1e-6;
  double x_tolerance = 1e-4;
  SolverOptions solver;  // for every local solve (on_iteration is called from worker threads)
  // A run that ends without a KKT point (and not stopped) is solved again from its final point, at
  // most `restarts` times (solve_with_restarts, solve.hpp). >= 0.
  int restarts = 0;
  // ... but not a run whose constraint violation is above this when it ends (solve_with_restarts). >= 0.
  double restart_max_violation = std::numeric_limits<double>::infinity();
  // The runs that count as successful (ranking, optima, successes, on_progress's best) and that are
  // not restarted: with kkt_only an "acceptable" run is restarted and, if it stays one, left out.
  Acceptance acceptance = Acceptance::kkt_or_acceptable;
  // Resume (issue 19 item 5): a run that recorded_run(i) returns is taken as run i instead of
  // being solved (its x is the final point); every run solved here to the end (not stopped by
  // should_stop) is passed to on_run_finished(i, run), one call at a time, from worker threads.
  std::function<std::optional<SolverSummary>(int)> recorded_run;
  std::function<void(int, const SolverSummary&)> on_run_finished;
  // Progress: after every run taken (solved to the end, or recorded_run), with the number of runs
  // taken so far and the lowest objective of the successful ones among them (NaN while none);
  // one call at a time, from worker threads.
  std::function<void(int runs_done, double best_objective)> on_progress;
};

// One distinct local optimum found by the successful runs (MultistartOptions::acceptance).
struct MultistartOptimum {
  double objective = 0.0;
  Eigen::VectorXd x;       // of the best run that reached it
  std::vector<int> starts;  // indices of the runs that reached it, ascending
};

struct MultistartResult {
  std::vector<Eigen::VectorXd> starts;      // x0 of run i
  std::vector<SolverSummary> runs;          // summary of run i
  std::vector<int> ranking;                 // successful runs by objective, best first (ties: lower index)
  std::vector<MultistartOptimum> optima;    // distinct optima, best first
  int successes = 0;                        // successful runs (MultistartOptions::acceptance)
  double wall_seconds = 0.0;
};

using ProblemFactory = std::function<std::unique_ptr<Problem>()>;
using StartSampler = std::function<Eigen::VectorXd(std::mt19937_64&)>;

// Throws std::invalid_argument for invalid options (naming the field). The sampler is called from
// worker threads and must not share mutable state.
MultistartResult multistart(const ProblemFactory& make_problem, const StartSampler& sample_start,
                            const MultistartOptions& options);
// The same from given starts (num_starts and base_seed are ignored; run i starts from starts[i]).
// Throws std::invalid_argument when starts is empty.
MultistartResult multistart_from(const ProblemFactory& make_problem, std::vector<Eigen::VectorXd> starts,
                                 const MultistartOptions& options);

}  // namespace cyclopt::nlp
