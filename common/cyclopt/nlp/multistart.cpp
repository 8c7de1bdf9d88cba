#include "cyclopt/nlp/multistart.hpp"

#include "cyclopt/nlp/solve.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace cyclopt::nlp {
namespace {

void validate(const MultistartOptions& o) {
  if (o.num_starts < 1) throw std::invalid_argument("MultistartOptions.num_starts: must be >= 1");
  if (o.num_threads < 0) throw std::invalid_argument("MultistartOptions.num_threads: must be >= 0 (0 = all cores)");
  if (!(o.objective_tolerance >= 0)) throw std::invalid_argument("MultistartOptions.objective_tolerance: must be >= 0");
  if (!(o.x_tolerance >= 0)) throw std::invalid_argument("MultistartOptions.x_tolerance: must be >= 0");
  if (o.restarts < 0) throw std::invalid_argument("MultistartOptions.restarts: must be >= 0");
  if (!(o.restart_max_violation >= 0.0))
    throw std::invalid_argument("MultistartOptions.restart_max_violation: must be >= 0 (infinity: every run)");
  validate(o.solver);
}

bool same_optimum(const SolverSummary& a, const SolverSummary& b, const MultistartOptions& o) {
  return std::abs(a.objective - b.objective) <= o.objective_tolerance * std::max(1.0, std::abs(a.objective)) &&
         a.x.size() == b.x.size() &&
         (a.x - b.x).lpNorm<Eigen::Infinity>() <= o.x_tolerance * std::max(1.0, a.x.lpNorm<Eigen::Infinity>());
}

}  // namespace

MultistartResult multistart(const ProblemFactory& make_problem, const StartSampler& sample_start,
                            const MultistartOptions& options) {
  validate(options);
  const auto start_time = std::chrono::steady_clock::now();
  const auto stopped = [&] { return options.solver.should_stop && options.solver.should_stop(); };
  std::vector<Eigen::VectorXd> starts(static_cast<size_t>(options.num_starts));
  for (int i = 0; i < options.num_starts; ++i) {
    if (stopped()) break;  // the unsampled starts stay empty and unsolved (user_stop)
    std::mt19937_64 rng(options.base_seed + static_cast<std::uint64_t>(i));
    starts[static_cast<size_t>(i)] = sample_start(rng);
  }
  MultistartResult result = multistart_from(make_problem, std::move(starts), options);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return result;
}

MultistartResult multistart_from(const ProblemFactory& make_problem, std::vector<Eigen::VectorXd> starts,
                            const MultistartOptions& options) {
  if (starts.empty()) throw std::invalid_argument("multistart: starts must not be empty");
  MultistartOptions sized = options;
  sized.num_starts = static_cast<int>(starts.size());
  validate(sized);
  const auto start_time = std::chrono::steady_clock::now();
  const int n = sized.num_starts;
  MultistartResult result;
  result.starts = std::move(starts);
  result.runs.resize(static_cast<size_t>(n));
  const auto stopped = [&] { return options.solver.should_stop && options.solver.should_stop(); };

  const int threads = std::min(n, options.num_threads > 0 ? options.num_threads
                                                          : std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  std::mutex finished_mutex;  // on_run_finished and on_progress are called one at a time
  int runs_done = 0;
  double best_objective = std::numeric_limits<double>::quiet_NaN();  // of the successful runs taken
  auto worker = [&] {
    try {
      const std::unique_ptr<Problem> problem = make_problem();
      for (int i = next++; i < n; i = next++) {
        SolverSummary& run = result.runs[static_cast<size_t>(i)];
        if (stopped()) {  // a start not begun: nothing to solve
          run.termination = Termination::user_stop;
          run.message = "not started: stopped by should_stop";
          continue;
        }
        std::optional<SolverSummary> recorded = options.recorded_run ? options.recorded_run(i) : std::nullopt;
        run = recorded ? std::move(*recorded)
                       : solve_with_restarts(*problem, options.solver, result.starts[static_cast<size_t>(i)],
                                             options.restarts, options.acceptance, options.restart_max_violation);
        if (run.termination == Termination::user_stop) continue;
        const std::lock_guard<std::mutex> lock(finished_mutex);
        if (options.on_run_finished && !recorded) options.on_run_finished(i, run);
        ++runs_done;
        if (accepted(run, options.acceptance) && !(run.objective >= best_objective)) best_objective = run.objective;
        if (options.on_progress) options.on_progress(runs_done, best_objective);
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = n;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);

  for (int i = 0; i < n; ++i)
    if (accepted(result.runs[static_cast<size_t>(i)], options.acceptance)) result.ranking.push_back(i);
  result.successes = static_cast<int>(result.ranking.size());
  std::stable_sort(result.ranking.begin(), result.ranking.end(), [&](int a, int b) {
    return result.runs[static_cast<size_t>(a)].objective < result.runs[static_cast<size_t>(b)].objective;
  });
  // Merge: walk the ranking best first; a run joins the first optimum it matches.
  for (int i : result.ranking) {
    const SolverSummary& run = result.runs[static_cast<size_t>(i)];
    auto match = std::find_if(result.optima.begin(), result.optima.end(), [&](const MultistartOptimum& o) {
      return same_optimum(result.runs[static_cast<size_t>(o.starts.front())], run, options);
    });
    if (match == result.optima.end())
      result.optima.push_back({run.objective, run.x, {i}});
    else
      match->starts.push_back(i);
  }
  for (MultistartOptimum& o : result.optima) std::sort(o.starts.begin(), o.starts.end());
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return result;
}

}  // namespace cyclopt::nlp
