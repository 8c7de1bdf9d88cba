#include "cyclopt/studies/speed_sweep.hpp"

#include "cyclopt/studies/walker_family.hpp"
#include "cyclopt/nlp/multistart.hpp"
#include "cyclopt/walker/starting_gait.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <stdexcept>

namespace cyclopt::studies {

using continuation::CurveJump;

namespace {

using Clock = std::chrono::steady_clock;

// A curve to continue from a solved point towards one end of the grid.
struct Task {
  Eigen::VectorXd x;
  double speed = 0.0;
  double direction = 1.0;  // +1 towards the largest speed
  int curve_id = 0;
  bool report_start = false;  // the start point is new (not reported by an earlier run)
};

class Sweep {
 public:
  Sweep(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem, const SpeedSweepOptions& o,
        const PointCallback& on_point)
      : model_(model), problem_(problem), o_(o), on_point_(on_point), family_(walker_family(model, problem, "speed")) {}

  SpeedSweepResult run();

 private:
  std::optional<Eigen::VectorXd> multistart_at(double v);
  bool on_known_curve(double v, const Eigen::VectorXd& x, double f) const;
  bool continue_task(const Task& t, std::deque<Task>& queue);
  void select_best();

  const walker::WalkerModel<double>& model_;
  const walker::GaitProblemOptions& problem_;
  const SpeedSweepOptions& o_;
  const PointCallback& on_point_;
  const ParametricProblem family_;
  SpeedSweepResult r_;
  bool stopped_ = false;
};

std::optional<Eigen::VectorXd> Sweep::multistart_at(double v) {
  walker::GaitProblemOptions po = problem_;
  po.speed = v;
  const walker::GaitEvaluator ev(model_);
  walker::StartingGaitOptions so;
  so.speed = v;
  const walker::StartingGait sg = walker::starting_gait(ev, so);
  if (!sg.real) return std::nullopt;
  const walker::GaitProblem shape(model_, po);
  nlp::MultistartOptions mo;
  mo.num_starts = o_.starts;
  mo.base_seed = o_.seed;
  mo.solver = o_.continuation.corrector;
  // Solves from perturbed starting gaits start from W_1 of (6.24) - the seed's choice, W_1 = I is
  // only its comparison with fmincon: HM P1 at 1.3 m/s needs ~300 instead of ~1800 iterations.
  mo.solver.sqp.difference_hessian = true;
  const nlp::MultistartResult m = nlp::multistart(
      [&] { return std::make_unique<walker::GaitProblem>(model_, po); },
      [&](std::mt19937_64& rng) { return shape.initial_point(walker::perturbed_gait(ev, sg.x, o_.scale, rng)); }, mo);
  r_.multistart_solves += o_.starts;
  r_.multistart_seconds += m.wall_seconds;
  if (m.optima.empty()) return std::nullopt;
  return m.optima.front().x;
}

bool Sweep::on_known_curve(double v, const Eigen::VectorXd& x, double f) const {
  for (const ContinuationResult& run : r_.runs)
    for (const CurvePoint& p : run.points)
      if (p.converged && p.parameter == v && std::abs(p.objective - f) <= o_.same_objective * std::max(1.0, std::abs(f)) &&
          (p.x - x).lpNorm<Eigen::Infinity>() <= o_.same_x)
        return true;
  return false;
}

// Continues one task; queues the backward continuation of every new curve it jumps to.
bool Sweep::continue_task(const Task& t, std::deque<Task>& queue) {
  std::vector<double> grid{t.speed};
  for (double v : o_.speeds)
    if ((v - t.speed) * t.direction > 1e-12) grid.push_back(v);
  if (t.direction < 0) std::sort(grid.begin() + 1, grid.end(), std::greater<>());
  if (grid.size() < 2) return true;
  bool repeated = !t.report_start;
  const PointCallback forward = [&](const CurvePoint& p) {
    const bool skip = repeated;
    repeated = false;
    return skip || !on_point_ || on_point_(p);
  };
  ContinuationOptions continuation = o_.continuation;
  continuation.corrector.max_iterations = std::min(continuation.corrector.max_iterations, o_.corrector_max_iterations);
  ContinuationResult run = continue_solution(family_, t.x, grid, continuation, {t.curve_id, r_.curves}, forward);
  r_.curves = std::max(r_.curves, run.next_curve_id);
  for (const CurveJump& j : run.jumps) {
    if (j.to_curve >= o_.max_curves) continue;
    for (const CurvePoint& p : run.points)
      if (p.curve_id == j.to_curve && p.parameter == j.to_parameter) {
        // A jump onto a curve an earlier run already followed (the same optimum at the same speed)
        // needs no second backward continuation.
        if (!on_known_curve(p.parameter, p.x, p.objective)) queue.push_back({p.x, p.parameter, -t.direction, j.to_curve, false});
        break;
      }
  }
  const bool go_on = run.message != "stopped";
  r_.runs.push_back(std::move(run));
  return go_on;
}

void Sweep::select_best() {
  for (double v : o_.speeds) {
    BestPoint b;
    b.speed = v;
    for (const ContinuationResult& run : r_.runs)
      for (const CurvePoint& p : run.points)
        if (p.converged && p.on_grid && std::abs(p.parameter - v) <= 1e-12 * std::max(1.0, v) &&
            (!b.found || p.objective < b.point.objective)) {
          b.found = true;
          b.point = p;
        }
    if (!b.found) b.reason = "no curve reached this speed with a KKT point";
    r_.best.push_back(std::move(b));
  }
}

SpeedSweepResult Sweep::run() {
  const Clock::time_point start = Clock::now();
  std::deque<Task> queue;
  for (double s : o_.seed_speeds) {
    const double v = *std::min_element(o_.speeds.begin(), o_.speeds.end(),
                                       [s](double a, double b) { return std::abs(a - s) < std::abs(b - s); });
    const std::optional<Eigen::VectorXd> x = multistart_at(v);
    if (!x) continue;
    nlp::Evaluation e;
    walker::GaitProblemOptions po = problem_;
    po.speed = v;
    if (!walker::GaitProblem(model_, po).evaluate(*x, false, e).ok || on_known_curve(v, *x, e.objective)) continue;
    if (r_.curves >= o_.max_curves) break;
    const int id = r_.curves++;
    queue.push_back({*x, v, 1.0, id, true});
    queue.push_back({*x, v, -1.0, id, false});
    while (!queue.empty() && !stopped_) {
      const Task t = std::move(queue.front());
      queue.pop_front();
      stopped_ = !continue_task(t, queue);
    }
    if (stopped_) break;
  }
  select_best();
  r_.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return std::move(r_);
}

}  // namespace

SpeedSweepResult speed_sweep(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                             const SpeedSweepOptions& options, const PointCallback& on_point) {
  validate(options.continuation);
  if (options.speeds.size() < 2 || !std::is_sorted(options.speeds.begin(), options.speeds.end()) ||
      std::adjacent_find(options.speeds.begin(), options.speeds.end()) != options.speeds.end())
    throw std::invalid_argument("speeds: need at least two strictly ascending values");
  if (options.seed_speeds.empty()) throw std::invalid_argument("seed_speeds: need at least one speed");
  if (options.starts < 1) throw std::invalid_argument("starts: must be >= 1");
  if (options.max_curves < 1) throw std::invalid_argument("max_curves: must be >= 1");
  if (options.corrector_max_iterations < 1) throw std::invalid_argument("corrector_max_iterations: must be >= 1");
  return Sweep(model, problem, options, on_point).run();
}

}  // namespace cyclopt::studies
