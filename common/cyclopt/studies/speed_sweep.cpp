#include "cyclopt/studies/speed_sweep.hpp"

#include "cyclopt/studies/walker_family.hpp"
#include "cyclopt/continuation/curve_jump.hpp"
#include "cyclopt/nlp/multistart.hpp"
#include "cyclopt/nlp/spare_core.hpp"
#include "cyclopt/nlp/wall_clock.hpp"
#include "cyclopt/walker/distant_start_solver.hpp"
#include "cyclopt/walker/starting_gait.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <deque>
#include <limits>
#include <map>
#include <mutex>
#include <set>
#include <stdexcept>
#include <tuple>

namespace cyclopt::studies {

using continuation::CurveJump;

namespace {

using nlp::Clock;
using nlp::seconds_since;

// SqpOptions::max_qp_iterations of the sweep's local solves, tighter than the design multistart's
// walker::kDistantStartQpIterations (200000, whose converged design runs needed up to 18695). Runs
// that drift far from any gait (violation 2..1400, f 10..1e15) go on solving l1-relaxed QPs of up to
// ~1000 variables, 200-1600 active-set iterations per SQP iteration, until MaxFun: P2-shoes HMT
// sweeps (bench/results/speed_sweep_bench.txt) had such runs of 26, 31, 32 and 154 s. No converged
// run of 1554 sweep solves (four feet, three seeds, variants) needed more than 10351.
constexpr int kQpIterations = 20000;

// A coarse solve that ends with at most this constraint violation found a gait on the coarse grid.
constexpr double kCoarseFeasible = 1e-6;
// The ETA's guess of a closure pass's solves per grid speed until one was measured: most speeds
// have no start left to try, the others start next to an optimum (measured on point feet, 21
// speeds: a pass took 3 s, 0.34 multistart solves' time per speed; bench/results/progress_honesty.txt).
constexpr double kClosureSolvesPerSpeed = 0.5;

bool same_speed(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); }

// The best optimum of a multistart (its optima are best first), if any.
std::optional<Eigen::VectorXd> best_optimum(const nlp::MultistartResult& m);

// A curve to continue from a solved point towards one end of the grid.
struct Task {
  Eigen::VectorXd x;
  double speed = 0.0;
  double direction = 1.0;  // +1 towards the largest speed
  int curve_id = 0;
  bool report_start = false;  // the start point is new (not reported by an earlier run)
  bool while_best = false;    // stops where another curve is at least as good (recovery, runner-ups)
};

// A grid speed to recover and the points to start from.
struct Target {
  std::size_t index = 0;  // into the grid
  bool unreached = true;  // else: the selected point may be dominated by `seeds`' curve
  std::vector<const CurvePoint*> seeds;
};

class Sweep {
 public:
  // One search with base seed `seed`; its curve ids begin at first_curve.
  Sweep(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem, const SpeedSweepOptions& o,
        SpeedSweepObserver& observer, std::uint64_t seed, int first_curve)
      : model_(model), problem_(problem), o_(o), observer_(observer), journal_(observer.journal()),
        family_(walker_family(model, problem, "speed")), seed_(seed), first_curve_(first_curve) {
    r_.curves = first_curve;
    r_.origins.resize(static_cast<std::size_t>(first_curve));
  }

  SpeedSweepResult run();

 private:
  walker::GaitProblemOptions at_speed(double v) const {
    walker::GaitProblemOptions po = problem_;
    po.speed = v;
    return po;
  }
  // Local solves at v from `starts`. coarse_first: a batch of perturbed starts, solved at
  // options.coarse_points first (SpeedSweepOptions::coarse_points).
  nlp::MultistartResult solve_from(double v, std::vector<Eigen::VectorXd> starts, bool coarse_first = false);
  // `before`: solves of the phase in earlier batches (a coarse batch before its polish), so the
  // phase's count runs on (20/22 .. 22/22) instead of starting again.
  nlp::MultistartResult solve_batch(const walker::WalkerModel<double>& model, double v, std::vector<Eigen::VectorXd> starts,
                                    int before = 0);
  // Multistart from perturbations of the automatic starting gait at v (none if it has no real solution).
  nlp::MultistartResult gait_multistart_at(double v, int* solves = nullptr);
  // Opens a curve through the optimum x at v and continues it both ways, unless there is none or it
  // lies on a known curve.
  void continue_new_optimum(double v, const std::optional<Eigen::VectorXd>& x, SweepStep step);
  // Step 2b: the runner-up optima of the seed multistart m at v, each continued while it is the best known.
  void continue_runner_ups(double v, const nlp::MultistartResult& m);
  // Opens a curve (origin) through the point x at v and continues it upwards, then downwards; while_best:
  // each run stops where another curve is at least as good.
  void open_and_continue(const Eigen::VectorXd& x, double v, const CurveOrigin& origin, bool while_best);
  bool on_known_curve(double v, const Eigen::VectorXd& x, double f) const;
  bool near_known_curve(const CurvePoint& p) const;
  // Grid speed i has no point and curves were opened since its last unreached recovery (or none ran).
  bool unreached_to_try(std::size_t i) const { return !r_.best[i].found && unreached_curves_[i] < r_.curves; }
  const CurvePoint* best_at(double v) const;
  int open_curve(const CurveOrigin& origin);
  // This search may open another curve: it opened fewer than max_curves (each search of several
  // seeds has its own; their ids run on, speed_sweep.hpp).
  bool curves_left() const { return r_.curves - first_curve_ < o_.max_curves; }
  // A continuation run of a task as computed, before the sweep takes it in (take_run).
  struct RunOutcome {
    ContinuationResult run;
    int number = 0;                    // journal key (runs_begun_ when it began)
    int first_new_curve = 0;           // the id it gave its first curve jumped to
    bool computed = false;             // else taken from the journal
    std::optional<double> merged;      // it stopped here: it joined an earlier run's curve
    std::optional<double> superseded;  // a recovery run stopped here: another curve is as good
  };
  void run_queue(std::deque<Task>& queue);
  std::vector<double> task_grid(const Task& t) const;  // the task's start speed, then the grid its way
  bool both_ways(const Task& up, const Task& down) const;
  std::optional<ContinuationResult> recorded_run(int number) const;
  // The run of t over grid (task_grid); its points go to the observer as they come, or (deferred) only
  // their indices are collected.
  RunOutcome compute_run(const Task& t, const std::vector<double>& grid, int number, int next_curve,
                         std::optional<ContinuationResult> recorded, std::vector<std::size_t>* deferred);
  void take_run(const Task& t, RunOutcome o, std::deque<Task>& queue);
  void continue_task(const Task& t, std::deque<Task>& queue);
  // continue_task with the task's grid (>= 2 values) and the journal's record of its run, if any.
  void run_task(const Task& t, const std::vector<double>& grid, std::optional<ContinuationResult> recorded,
                std::deque<Task>& queue);
  void continue_both_ways(const Task& up, const Task& down, std::deque<Task>& queue);
  std::optional<Target> next_target();
  void recover(const Target& target);
  // The closure of the envelope (speed_sweep.hpp) and its starts at grid speed i not tried there yet.
  void close_envelope();
  std::vector<const CurvePoint*> closure_starts(std::size_t i);
  bool closure_pass(int pass);  // true if it improved a best point
  void mark_tried(std::size_t i, const CurvePoint& p) { tried_starts_.insert({i, p.curve_id, p.parameter}); }
  void select_best();
  void begin_phase(SweepPhase phase, std::string detail, int total);
  int label(int curve_id) const { return curve_id + o_.curve_label_offset; }  // as texts name it
  void report();  // observer_.on_progress of the current state; callers hold progress_mutex_
  // The observer takes p; false, and the sweep stops, once it asked to stop (then it is not called again).
  bool hand_over(const CurvePoint& p);
  double eta_seconds() const;
  // A converged point: marks its grid speed reached; `step`: it is the running run's next point.
  void reached(const CurvePoint& p, bool step);

  const walker::WalkerModel<double>& model_;
  const walker::GaitProblemOptions& problem_;
  const SpeedSweepOptions& o_;
  SpeedSweepObserver& observer_;
  const SweepJournal journal_;
  const ParametricProblem family_;
  const std::uint64_t seed_;
  const int first_curve_;
  SpeedSweepResult r_;
  bool stopped_ = false;
  SweepPhase run_phase_ = SweepPhase::continuation;  // progress phase of continuation runs (recovery, closure)
  std::vector<bool> seeded_;                    // per grid speed: a gait multistart ran there
  // Per grid speed: the curves there were (r_.curves) when its unreached recovery was last tried,
  // -1 before any; it is tried again once curves were opened since, from those curves only.
  std::vector<int> unreached_curves_;
  std::set<std::pair<std::size_t, int>> dominance_tried_;  // (grid speed, neighbour's curve)
  std::map<std::size_t, std::string> failures_;  // per grid speed: what recovery tried
  std::map<std::size_t, std::string> tried_from_;  // per grid speed: the R1 starts of its tries
  std::set<std::tuple<std::size_t, int, double>> tried_starts_;  // (grid speed, curve, its point's speed)
  std::vector<int> closure_passes_;             // per grid speed: closure passes that solved there
  std::map<int, int> closure_curves_;           // curve id -> the closure pass that opened it
  int batches_ = 0;                             // multistart batches begun (journal keys)
  int runs_begun_ = 0;                          // continuation runs begun (journal keys)

  // Progress (sweep_progress.hpp); the mutex serialises reports from multistart workers.
  std::mutex progress_mutex_;
  SweepProgress progress_;
  std::vector<bool> reached_;                    // per grid speed: a converged point on some curve
  int seed_batches_left_ = 0;                   // seed speeds whose multistart has not begun
  int computed_solves_ = 0;                     // multistart solves finished in this attempt (not resumed)
  Clock::time_point batch_start_;
  double continuation_wall_ = 0.0;              // of finished runs
  int recoveries_left_ = 0;                     // unreached speeds with curves not tried yet (in recovery)
  Clock::time_point closure_start_;             // of the closure
  std::size_t closure_visited_ = 0;             // grid speeds the closure's passes went through
  std::size_t closure_next_ = 0;                // the pass's grid speed being solved
  int closure_solved_ = 0;                      // grid speeds with starts the closure solved
  bool closure_ended_ = false;
};

void Sweep::begin_phase(SweepPhase phase, std::string detail, int total) {
  const std::lock_guard lock(progress_mutex_);
  progress_.phase = phase;
  progress_.detail = std::move(detail);
  progress_.phase_done = 0;
  progress_.phase_total = total;
  if (phase == SweepPhase::multistart) progress_.best_objective = SweepProgress::kNaN;
  report();
}

void Sweep::reached(const CurvePoint& p, bool step) {
  const std::lock_guard lock(progress_mutex_);
  if (step && p.on_grid) ++progress_.phase_done;  // grid speeds passed by this run
  for (std::size_t i = 0; i < o_.speeds.size(); ++i)
    if (same_speed(o_.speeds[i], p.parameter) && !reached_[i]) {
      reached_[i] = true;
      ++progress_.speeds_reached;
    }
  if (!(p.objective >= progress_.best_objective)) progress_.best_objective = p.objective;
  report();
}

double Sweep::eta_seconds() const {
  const double batch_wall = progress_.phase == SweepPhase::multistart ? seconds_since(batch_start_) : 0.0;
  const double solve_rate = computed_solves_ > 0 ? (r_.multistart_seconds + batch_wall) / computed_solves_ : SweepProgress::kNaN;
  const int unreached = progress_.speeds_total - progress_.speeds_reached;
  // The closure: the grid speeds of the pass left at its measured seconds per speed (once a speed
  // with starts was solved; before, kClosureSolvesPerSpeed solves per speed); one pass - whether
  // another follows cannot be foreseen.
  double closure = 0.0;
  if (o_.closure.enabled && !closure_ended_) {
    const double per_speed = closure_solved_ > 0 && closure_visited_ > 0 ? seconds_since(closure_start_) / closure_visited_
                                                                         : kClosureSolvesPerSpeed * solve_rate;
    const std::size_t visited = progress_.phase == SweepPhase::closure ? closure_next_ : 0;
    closure = static_cast<double>(o_.speeds.size() - visited) * per_speed;
  }
  if (progress_.phase == SweepPhase::closure) return closure;
  if (progress_.phase == SweepPhase::recovery) {
    const int done = static_cast<int>(r_.recoveries.size());
    const double per_target = done > 0 ? r_.recovery_seconds / done : o_.starts * solve_rate;
    return recoveries_left_ * per_target + closure;
  }
  const int batch_left = progress_.phase == SweepPhase::multistart ? progress_.phase_total - progress_.phase_done : 0;
  const double speed_rate = progress_.speeds_reached > 0 && continuation_wall_ > 0.0
                                ? continuation_wall_ / progress_.speeds_reached : solve_rate;
  return (seed_batches_left_ * o_.starts + batch_left) * solve_rate + unreached * speed_rate + closure;
}

bool Sweep::hand_over(const CurvePoint& p) {
  if (!r_.stopped && observer_.on_point(p)) return true;
  r_.stopped = stopped_ = true;
  return false;
}

void Sweep::report() {
  progress_.eta_seconds = eta_seconds();
  observer_.on_progress(progress_);
}

nlp::MultistartResult Sweep::solve_from(double v, std::vector<Eigen::VectorXd> starts, bool coarse_first) {
  if (!coarse_first || o_.coarse_points == 0 || o_.coarse_points >= model_.constants.points)
    return solve_batch(model_, v, std::move(starts));
  walker::WalkerModel<double> coarse = model_;
  coarse.constants.points = o_.coarse_points;
  const nlp::MultistartResult c = solve_batch(coarse, v, starts);
  std::vector<Eigen::VectorXd> optima;
  for (const nlp::MultistartOptimum& optimum : c.optima) optima.push_back(optimum.x);
  // No coarse optimum: all starts at P if the coarse grid may lack the gait (no coarse run ended
  // feasible); else the batch found none (SpeedSweepOptions::coarse_points).
  if (optima.empty() && std::any_of(c.runs.begin(), c.runs.end(), [](const nlp::SolverSummary& run) {
        return run.termination != nlp::Termination::evaluation_failure && run.termination != nlp::Termination::user_stop &&
               run.constraint_violation <= kCoarseFeasible;
      }))
    return c;
  nlp::MultistartResult fine = solve_batch(model_, v, optima.empty() ? std::move(starts) : std::move(optima),
                                           static_cast<int>(c.runs.size()));
  fine.runs.insert(fine.runs.begin(), c.runs.begin(), c.runs.end());  // every solve counts
  return fine;
}

nlp::MultistartResult Sweep::solve_batch(const walker::WalkerModel<double>& model, double v, std::vector<Eigen::VectorXd> starts,
                                         int before) {
  const walker::GaitProblemOptions po = at_speed(v);
  nlp::MultistartOptions mo;
  mo.solver = walker::distant_start_solver(o_.continuation.corrector);
  mo.solver.sqp.progress_window = walker::kMultistartProgressWindow;
  mo.solver.sqp.max_qp_iterations = kQpIterations;
  const int batch = batches_++;
  std::atomic<int> resumed{0};
  journal_multistart(mo, journal_, batch, &resumed);
  const int n = static_cast<int>(starts.size());
  {
    const std::lock_guard lock(progress_mutex_);
    progress_.phase_total = before + n;
    batch_start_ = Clock::now();
  }
  const int computed_before = computed_solves_;
  mo.on_progress = [&](int done, double best) {
    const std::lock_guard lock(progress_mutex_);
    progress_.phase_done = before + done;
    computed_solves_ = computed_before + done - resumed;
    // The lowest objective seen in the phase (begin_phase resets it for a seed batch).
    if (std::isfinite(best) && !(best >= progress_.best_objective)) progress_.best_objective = best;
    report();
  };
  const std::clock_t cpu = std::clock();
  nlp::MultistartResult m = nlp::multistart_from([&] { return std::make_unique<walker::GaitProblem>(model, po); },
                                            std::move(starts), mo);
  r_.multistart_solves += n - resumed;
  r_.resumed_solves += resumed;
  {
    const std::lock_guard lock(progress_mutex_);  // eta_seconds reads both
    r_.multistart_seconds += m.wall_seconds;
    batch_start_ = Clock::now();  // the batch's wall is in multistart_seconds now
  }
  r_.multistart_cpu_seconds += static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
  return m;
}

nlp::MultistartResult Sweep::gait_multistart_at(double v, int* solves) {
  const walker::GaitEvaluator ev(model_);
  walker::StartingGaitOptions so;
  so.speed = v;
  const walker::StartingGait sg = walker::starting_gait(ev, so);
  if (!sg.real) return {};
  const walker::GaitProblem shape(model_, at_speed(v));
  std::vector<Eigen::VectorXd> starts;
  for (int i = 0; i < o_.starts; ++i) {
    std::mt19937_64 rng(seed_ + static_cast<std::uint64_t>(i));
    starts.push_back(shape.initial_point(walker::perturbed_gait(ev, sg.x, o_.scale, rng)));
  }
  if (solves) *solves += o_.starts;
  return solve_from(v, std::move(starts), true);
}

std::optional<Eigen::VectorXd> best_optimum(const nlp::MultistartResult& m) {
  if (m.optima.empty()) return std::nullopt;
  return m.optima.front().x;
}

void Sweep::continue_new_optimum(double v, const std::optional<Eigen::VectorXd>& x, SweepStep step) {
  if (!x) return;
  nlp::Evaluation e;
  if (!walker::GaitProblem(model_, at_speed(v)).evaluate(*x, false, e).ok || on_known_curve(v, *x, e.objective)) return;
  open_and_continue(*x, v, {step, v}, false);
}

void Sweep::continue_runner_ups(double v, const nlp::MultistartResult& m) {
  const int count = std::min(o_.runner_ups, static_cast<int>(m.optima.size()) - 1);
  if (count < 1) return;
  const double best = m.optima.front().objective;
  for (int k = 1; k <= count && !stopped_ && curves_left(); ++k) {
    const nlp::MultistartOptimum& optimum = m.optima[static_cast<std::size_t>(k)];
    if (optimum.objective - best > o_.runner_up_margin * std::max(std::abs(best), 1e-12)) break;
    if (on_known_curve(v, optimum.x, optimum.objective)) continue;  // a run from a better optimum passed it
    open_and_continue(optimum.x, v, {SweepStep::seed_multistart, v}, true);
  }
}

void Sweep::open_and_continue(const Eigen::VectorXd& x, double v, const CurveOrigin& origin, bool while_best) {
  const int id = open_curve(origin);
  std::deque<Task> queue{{x, v, 1.0, id, true, while_best}, {x, v, -1.0, id, false, while_best}};
  run_queue(queue);
}

bool Sweep::on_known_curve(double v, const Eigen::VectorXd& x, double f) const {
  for (const ContinuationResult& run : r_.runs)
    for (const CurvePoint& p : run.points)
      if (p.converged && p.parameter == v && std::abs(p.objective - f) <= o_.same_objective * std::max(1.0, std::abs(f)) &&
          (p.x - x).lpNorm<Eigen::Infinity>() <= o_.same_x)
        return true;
  return false;
}

// A point that is one optimum (continuation::same_optimum_nearby) with a converged point of another
// curve an earlier run followed. A curve jumped to there needs no backward continuation: it would
// retrace that curve. Without this test two curves that each end at a fold inside one grid interval
// kept jumping onto each other: the rho 10 low-speed design of the foot design study (band 1e-3)
// went back and forth between 0.905 and 0.985 m/s in 17 runs, each landing 1e-4..3e-3 (max norm)
// and 0.001..0.002 m/s from a point found before, until the curves (max_curves) ran out and 0.4
// and 0.5 m/s, found by recovery, could not be continued (19/21 speeds; 21/21 with the test).
bool Sweep::near_known_curve(const CurvePoint& p) const {
  for (const ContinuationResult& run : r_.runs)
    for (const CurvePoint& q : run.points)
      if (q.converged && q.curve_id != p.curve_id &&
          continuation::same_optimum_nearby(p.parameter, p.x, q.parameter, q.x, o_.continuation))
        return true;
  return false;
}

const CurvePoint* Sweep::best_at(double v) const {
  const CurvePoint* best = nullptr;
  for (const ContinuationResult& run : r_.runs)
    for (const CurvePoint& p : run.points)
      if (p.converged && p.on_grid && same_speed(p.parameter, v) && (!best || p.objective < best->objective)) best = &p;
  return best;
}

int Sweep::open_curve(const CurveOrigin& origin) {
  r_.origins.resize(static_cast<std::size_t>(r_.curves) + 1);
  r_.origins.back() = origin;
  return r_.curves++;
}

void Sweep::run_queue(std::deque<Task>& queue) {
  while (!queue.empty() && !stopped_) {
    const Task t = std::move(queue.front());
    queue.pop_front();
    if (!queue.empty() && both_ways(t, queue.front()) && nlp::core_is_spare()) {
      const Task down = std::move(queue.front());
      queue.pop_front();
      continue_both_ways(t, down, queue);
    } else {
      continue_task(t, queue);
    }
  }
}

std::vector<double> Sweep::task_grid(const Task& t) const {
  std::vector<double> grid{t.speed};
  for (double v : o_.speeds)
    if ((v - t.speed) * t.direction > 1e-12) grid.push_back(v);
  if (t.direction < 0) std::sort(grid.begin() + 1, grid.end(), std::greater<>());
  return grid;
}

// The upward and the downward run from one new point (continue_new_optimum, recover): the downward
// run's points all lie below the start speed, where the upward run has none, so nothing the upward
// run adds (merge and superseded tests, on_known_curve, best_at) can change the downward run.
bool Sweep::both_ways(const Task& up, const Task& down) const {
  return up.direction > 0 && down.direction < 0 && up.speed == down.speed && up.curve_id == down.curve_id &&
         !down.report_start && up.x == down.x && task_grid(up).size() >= 2 && task_grid(down).size() >= 2;
}

Sweep::RunOutcome Sweep::compute_run(const Task& t, const std::vector<double>& grid, int number, int next_curve,
                                     std::optional<ContinuationResult> recorded, std::vector<std::size_t>* deferred) {
  RunOutcome o;
  o.number = number;
  o.first_new_curve = next_curve;
  bool repeated = !t.report_start;
  std::size_t emitted = 0;
  const PointCallback forward = [&](const CurvePoint& p) {
    const bool skip = repeated;
    repeated = false;
    const std::size_t index = emitted++;
    if (!skip && deferred) deferred->push_back(index);
    if (!skip && !deferred && !hand_over(p)) return false;
    if (!skip && p.converged) reached(p, !same_speed(p.parameter, t.speed));  // the start is no step
    if (skip || !p.converged || !p.on_grid) return true;
    // An earlier run followed this curve from here on already (both directions are continued
    // from every start and every curve jumped to): HMT P2's runs from 1.3, 1.5 and 2.3 m/s
    // otherwise each went down to the same fold near 0.46 m/s (~27 s each).
    if (on_known_curve(p.parameter, p.x, p.objective)) {
      o.merged = p.parameter;
      return false;
    }
    if (t.while_best && !same_speed(p.parameter, t.speed)) {  // a runner-up starts below the best at its speed
      const CurvePoint* other = best_at(p.parameter);
      if (other && other->objective <= p.objective + o_.same_objective * std::max(1.0, std::abs(p.objective))) {
        o.superseded = p.parameter;
        return false;
      }
    }
    return true;
  };
  if (recorded) {
    // The run as an earlier attempt computed it: its points go through the same callback (the store
    // skips those it holds), so merge stops, curve numbering and the later steps are unchanged.
    o.run = std::move(*recorded);
    for (const CurvePoint& p : o.run.points)
      if (!forward(p)) break;
    return o;
  }
  ContinuationOptions continuation = o_.continuation;
  continuation.corrector.max_iterations = std::min(continuation.corrector.max_iterations, o_.corrector_max_iterations);
  continuation::StateCallback record_state;
  if (journal_.record_run_state)
    record_state = [this, number](const continuation::RunState& s) { journal_.record_run_state(number, s); };
  o.computed = true;
  std::optional<continuation::RunState> state = journal_.find_run_state ? journal_.find_run_state(number) : std::nullopt;
  if (state && !state->result.points.empty() && state->result.points.back().converged) {
    // An earlier attempt got this far: its points go through the callback as a recorded run's do,
    // and the run goes on from its last converged point. A state recorded while the ids of the
    // run's new curves were provisional (continue_both_ways) is renumbered from the id it began with.
    const int began_with = state->result.next_curve_id - static_cast<int>(state->result.jumps.size());
    if (began_with != next_curve) continuation::renumber_new_curves(*state, began_with, next_curve);
    for (const CurvePoint& p : state->result.points)
      if (!forward(p)) {  // the job stops, or the run ends where the uninterrupted one did not
        o.run = std::move(state->result);
        o.run.message = "stopped";
        return o;
      }
    o.run = resume_solution(family_, *state, grid, continuation, forward, record_state);
    return o;
  }
  o.run = continue_solution(family_, t.x, grid, continuation, {t.curve_id, next_curve}, forward, record_state);
  return o;
}

void Sweep::take_run(const Task& t, RunOutcome o, std::deque<Task>& queue) {
  ContinuationResult& run = o.run;
  ++(o.computed ? r_.computed_runs : r_.resumed_runs);
  for (const CurvePoint& p : run.points)  // the start point too, which the callback may skip
    if (p.converged) reached(p, false);
  for (int c = o.first_new_curve; c < run.next_curve_id; ++c) r_.origins.push_back({SweepStep::jump, 0.0});
  r_.curves = std::max(r_.curves, run.next_curve_id);
  for (const CurveJump& j : run.jumps) {
    r_.origins[static_cast<std::size_t>(j.to_curve)].speed = j.to_parameter;
    if (j.to_curve - first_curve_ >= o_.max_curves) continue;
    for (const CurvePoint& p : run.points)
      if (p.curve_id == j.to_curve && p.parameter == j.to_parameter) {
        // A jump onto a curve an earlier run already followed (the same optimum at the same speed,
        // or next to one of its points) needs no second backward continuation.
        if (!on_known_curve(p.parameter, p.x, p.objective) && !near_known_curve(p))
          queue.push_back({p.x, p.parameter, -t.direction, j.to_curve, false, t.while_best});
        break;
      }
  }
  if (o.merged && !stopped_)
    run.message = "stopped at " + std::to_string(*o.merged) + " m/s: joined a curve an earlier run followed";
  else if (o.superseded && !stopped_)
    run.message = "stopped at " + std::to_string(*o.superseded) + " m/s: another curve is as good from there on";
  else if (run.message == "stopped")  // the corrector's iteration callback asked to stop
    stopped_ = true;
  if (o.computed && !stopped_ && journal_.record_run) journal_.record_run(o.number, run);
  r_.runs.push_back(std::move(run));
}

std::optional<ContinuationResult> Sweep::recorded_run(int number) const {
  return journal_.find_run ? journal_.find_run(number) : std::nullopt;
}

// Continues one task; queues the backward continuation of every new curve it jumps to.
void Sweep::continue_task(const Task& t, std::deque<Task>& queue) {
  const std::vector<double> grid = task_grid(t);
  if (grid.size() >= 2) run_task(t, grid, recorded_run(runs_begun_), queue);
}

void Sweep::run_task(const Task& t, const std::vector<double>& grid, std::optional<ContinuationResult> recorded,
                     std::deque<Task>& queue) {
  const Clock::time_point run_start = Clock::now();
  char detail[96];
  std::snprintf(detail, sizeof detail, "run %d from %.4g m/s %s, curve %d", runs_begun_ + 1, t.speed,
                t.direction > 0 ? "upwards" : "downwards", label(t.curve_id));
  begin_phase(run_phase_, detail, static_cast<int>(grid.size()) - 1);
  const int number = runs_begun_++;
  RunOutcome o = compute_run(t, grid, number, r_.curves, std::move(recorded), nullptr);
  if (o.computed) {
    const std::lock_guard lock(progress_mutex_);
    continuation_wall_ += seconds_since(run_start);
  }
  take_run(t, std::move(o), queue);
}

// continue_task(up) and continue_task(down) (both_ways), the two runs computed at once on a spare
// core (nlp/spare_core.hpp) - the same runs, points and curve ids as one after the other. The
// downward run's points reach on_point only once the upward run has ended, in their order, so the
// store sees the sequence it would see from one thread; its curves jumped to are numbered after
// the upward run's. Runs an earlier attempt recorded are taken one after the other.
void Sweep::continue_both_ways(const Task& up, const Task& down, std::deque<Task>& queue) {
  const int first = runs_begun_;
  const std::vector<double> up_grid = task_grid(up), down_grid = task_grid(down);
  std::optional<ContinuationResult> recorded_up = recorded_run(first), recorded_down = recorded_run(first + 1);
  const bool begun = journal_.find_run_state && (journal_.find_run_state(first) || journal_.find_run_state(first + 1));
  if (recorded_up || recorded_down || begun) {
    run_task(up, up_grid, std::move(recorded_up), queue);
    if (!stopped_) run_task(down, down_grid, std::move(recorded_down), queue);
    return;
  }
  const Clock::time_point run_start = Clock::now();
  char detail[96];
  std::snprintf(detail, sizeof detail, "runs %d and %d from %.4g m/s upwards and downwards, curve %d", first + 1, first + 2,
                up.speed, label(up.curve_id));
  begin_phase(run_phase_, detail,
              static_cast<int>(up_grid.size() + down_grid.size()) - 2);
  runs_begun_ += 2;
  // Provisional ids of the downward run's curves jumped to, renumbered once the upward run's are known.
  const int provisional = r_.curves + (1 << 20);
  RunOutcome upward, downward;
  std::vector<std::size_t> deferred;  // indices of the downward run's points to report
  nlp::split_on_spare_core(2, 2, [&](int begin, int end, bool) {
    for (int i = begin; i < end; ++i)
      if (i == 0)
        upward = compute_run(up, up_grid, first, r_.curves, std::nullopt, nullptr);
      else
        downward = compute_run(down, down_grid, first + 1, provisional, std::nullopt, &deferred);
  });
  {
    const std::lock_guard lock(progress_mutex_);
    continuation_wall_ += seconds_since(run_start);
  }
  continuation::renumber_new_curves(downward.run, provisional, upward.run.next_curve_id);
  downward.first_new_curve = upward.run.next_curve_id;
  take_run(up, std::move(upward), queue);
  if (stopped_) return;
  for (std::size_t index : deferred)
    if (!hand_over(downward.run.points[index])) {  // the job stops: the run ends at this point
      downward.run.points.resize(index + 1);
      downward.run.message = "stopped";
      break;
    }
  take_run(down, std::move(downward), queue);
}

// Unreached speeds first (nearest to a reached one, then the lowest), then possibly dominated ones.
std::optional<Target> Sweep::next_target() {
  const std::size_t n = o_.speeds.size();
  std::optional<Target> best;
  std::size_t best_distance = n;
  for (std::size_t i = 0; i < n; ++i) {
    if (!unreached_to_try(i)) continue;
    std::size_t distance = n;
    for (std::size_t j = 0; j < n; ++j)
      if (r_.best[j].found) distance = std::min(distance, i > j ? i - j : j - i);
    if (!best || distance < best_distance) {
      best = Target{i, true, {}};
      best_distance = distance;
    }
  }
  if (best) {
    // R1 starts: the converged point nearest in speed to the target of every curve not tried there.
    const double v = o_.speeds[best->index];
    const int first_curve = std::max(0, unreached_curves_[best->index]);
    std::map<int, const CurvePoint*> nearest;
    for (const ContinuationResult& run : r_.runs)
      for (const CurvePoint& p : run.points) {
        if (p.curve_id < first_curve) continue;
        const CurvePoint*& q = nearest[p.curve_id];
        if (p.converged && (!q || std::abs(p.parameter - v) < std::abs(q->parameter - v))) q = &p;
      }
    for (const auto& [curve, p] : nearest)
      if (p) best->seeds.push_back(p);
    std::sort(best->seeds.begin(), best->seeds.end(), [v](const CurvePoint* a, const CurvePoint* b) {
      return std::abs(a->parameter - v) < std::abs(b->parameter - v);
    });
    return best;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!r_.best[i].found) continue;
    const double v = o_.speeds[i];
    for (std::size_t j : {i - 1, i + 1}) {  // i - 1 wraps to a huge value for i = 0
      if (j >= n || !r_.best[j].found) continue;
      const CurvePoint& neighbour = r_.best[j].point;
      if (neighbour.curve_id == r_.best[i].point.curve_id || dominance_tried_.count({i, neighbour.curve_id})) continue;
      bool reaches = false;  // the neighbour's curve has a converged point at v already
      for (const ContinuationResult& run : r_.runs)
        for (const CurvePoint& p : run.points) reaches = reaches || (p.converged && p.curve_id == neighbour.curve_id && same_speed(p.parameter, v));
      dominance_tried_.insert({i, neighbour.curve_id});
      if (!reaches) return Target{i, false, {&neighbour}};
    }
  }
  return std::nullopt;
}

void Sweep::recover(const Target& target) {
  const Clock::time_point t0 = Clock::now();
  const double v = o_.speeds[target.index];
  recoveries_left_ = 0;
  for (std::size_t i = 0; i < o_.speeds.size(); ++i) recoveries_left_ += unreached_to_try(i);
  char detail[64];
  std::snprintf(detail, sizeof detail, "at %.4g m/s (%s)", v, target.unreached ? "unreached" : "dominated?");
  begin_phase(SweepPhase::recovery, detail, -1);
  RecoveryAttempt a;
  a.speed = v;
  const bool retry = target.unreached && unreached_curves_[target.index] >= 0;
  a.trigger = target.unreached ? (retry ? "unreached, again from curves opened since" : "unreached")
                               : "dominated? curve " + std::to_string(label(target.seeds.front()->curve_id)) + " is best at " +
                                     std::to_string(target.seeds.front()->parameter) + " m/s";
  // A recovered point must beat the selected one (if any) by more than same_objective.
  const CurvePoint* current = best_at(v);
  const double bound = current ? current->objective - o_.same_objective * std::max(1.0, std::abs(current->objective))
                               : std::numeric_limits<double>::infinity();
  std::optional<Eigen::VectorXd> x;
  double f = bound;
  auto take = [&](const nlp::MultistartResult& m, SweepStep step) {
    a.solves += static_cast<int>(m.runs.size());
    if (m.optima.empty() || !(m.optima.front().objective < bound)) return false;
    x = m.optima.front().x;
    f = m.optima.front().objective;
    a.step = step;
    return true;
  };
  std::vector<Eigen::VectorXd> starts;
  std::string curves;
  for (const CurvePoint* p : target.seeds) {
    mark_tried(target.index, *p);
    starts.push_back(p->x);
    curves += (curves.empty() ? "" : ", ") + std::to_string(label(p->curve_id)) + " at " + std::to_string(p->parameter);
  }
  const nlp::MultistartResult r1 = starts.empty() ? nlp::MultistartResult{} : solve_from(v, starts);
  bool found = !starts.empty() && take(r1, SweepStep::neighbour_start);
  // R2 also where the neighbour's optimum leads to no KKT point at v (its curve ends at a fold
  // before v), so a possibly dominated point is not kept just because R1 could not start there.
  if (!found && !starts.empty() && (target.unreached || r1.successes == 0)) {
    const walker::GaitProblem shape(model_, at_speed(v));
    const walker::GaitEvaluator ev(model_);
    std::vector<Eigen::VectorXd> perturbed;
    const int count = target.unreached || o_.dominance_starts == 0 ? o_.starts : o_.dominance_starts;
    for (int i = 0; i < count; ++i) {
      std::mt19937_64 rng(seed_ + static_cast<std::uint64_t>(i));
      Eigen::VectorXd z = starts[static_cast<std::size_t>(i) % starts.size()];
      z.head(shape.gait_parameters(z).size()) = walker::perturbed_gait(ev, shape.gait_parameters(z), o_.scale, rng);
      perturbed.push_back(std::move(z));
    }
    found = take(solve_from(v, std::move(perturbed), true), SweepStep::neighbour_multistart);
  }
  if (!found && target.unreached && !seeded_[target.index]) {
    seeded_[target.index] = true;
    int solves = 0;
    const std::optional<Eigen::VectorXd> g = best_optimum(gait_multistart_at(v, &solves));
    a.solves += solves;
    if (g) {
      nlp::Evaluation e;
      walker::GaitProblem(model_, at_speed(v)).evaluate(*g, false, e);
      x = g;
      f = e.objective;
      a.step = SweepStep::gait_multistart;
      found = true;
    }
  }
  if (target.unreached) unreached_curves_[target.index] = r_.curves;
  if (found && curves_left()) {
    a.found = true;
    a.objective = f;
    open_and_continue(*x, v, {a.step, v}, true);
  } else if (target.unreached) {
    std::string& from = tried_from_[target.index];
    from += (from.empty() || curves.empty() ? "" : ", ") + curves;
    failures_[target.index] =
        found ? "a KKT point was found by recovery but max_curves (" + std::to_string(o_.max_curves) + ") curves are in use"
              : "no KKT point: continuation did not reach this speed; R1 solves here from the nearest points of curves (" +
                    from + " m/s), R2 " + std::to_string(o_.starts) +
                    " perturbations of them and the starting-gait multistart here found none; more starts (starts), "
                    "another seed or a smaller continuation.min_trust_region may help";
  }
  a.seconds = seconds_since(t0);
  r_.recovery_seconds += a.seconds;
  r_.recoveries.push_back(std::move(a));
}

std::vector<const CurvePoint*> Sweep::closure_starts(std::size_t i) {
  const std::size_t n = o_.speeds.size();
  const double v = o_.speeds[i];
  // One grid step: the wider of the two intervals next to v.
  double step = 0.0;
  if (i > 0) step = std::max(step, v - o_.speeds[i - 1]);
  if (i + 1 < n) step = std::max(step, o_.speeds[i + 1] - v);
  step *= 1.0 + 1e-9;
  std::map<int, const CurvePoint*> nearest;  // per curve without a converged point at v
  std::set<int> at_v;
  for (const ContinuationResult& run : r_.runs)
    for (const CurvePoint& p : run.points) {
      if (!p.converged) continue;
      if (same_speed(p.parameter, v)) {
        at_v.insert(p.curve_id);
        continue;
      }
      const double d = std::abs(p.parameter - v);
      const CurvePoint*& q = nearest[p.curve_id];
      if (d <= step && (!q || d < std::abs(q->parameter - v))) q = &p;
    }
  std::vector<const CurvePoint*> candidates;
  for (std::size_t j : {i - 1, i + 1})  // i - 1 wraps to a huge value for i = 0
    if (j < n && r_.best[j].found) {
      const CurvePoint* p = best_at(o_.speeds[j]);
      if (p) candidates.push_back(p);
    }
  for (const auto& [curve, p] : nearest)
    if (p) candidates.push_back(p);
  std::vector<const CurvePoint*> starts;
  for (const CurvePoint* p : candidates) {
    if (at_v.count(p->curve_id) || tried_starts_.count({i, p->curve_id, p->parameter})) continue;
    mark_tried(i, *p);
    starts.push_back(p);
  }
  return starts;
}

bool Sweep::closure_pass(int pass) {
  bool improved = false;
  for (std::size_t i = 0; i < o_.speeds.size() && !stopped_; ++i) {
    {
      const std::lock_guard lock(progress_mutex_);  // eta_seconds reads them
      closure_next_ = i;
      closure_visited_ = static_cast<std::size_t>(pass - 1) * o_.speeds.size() + i;
    }
    const std::vector<const CurvePoint*> from = closure_starts(i);
    if (from.empty()) continue;
    ++closure_passes_[i];
    const double v = o_.speeds[i];
    char detail[64];
    std::snprintf(detail, sizeof detail, "pass %d at %.4g m/s", pass, v);
    begin_phase(SweepPhase::closure, detail, static_cast<int>(from.size()));
    std::vector<Eigen::VectorXd> starts;
    for (const CurvePoint* p : from) starts.push_back(p->x);
    const nlp::MultistartResult m = solve_from(v, std::move(starts));
    {
      const std::lock_guard lock(progress_mutex_);
      ++closure_solved_;
    }
    r_.closure.solves += static_cast<int>(m.runs.size());
    if (m.optima.empty()) continue;
    const double f = m.optima.front().objective;
    const CurvePoint* current = best_at(v);
    if (current && !(current->objective - f > o_.closure.min_improvement * std::max(std::abs(current->objective), 1e-12)))
      continue;
    if (!curves_left()) {
      r_.closure.reason = "a better point was found but max_curves (" + std::to_string(o_.max_curves) + ") curves are in use";
      return false;
    }
    closure_curves_[r_.curves] = pass;
    open_and_continue(m.optima.front().x, v, {SweepStep::closure, v}, true);
    select_best();  // the neighbours' best points for the next speeds
    improved = true;
  }
  return improved;
}

void Sweep::close_envelope() {
  EnvelopeClosure& c = r_.closure;
  if (!o_.closure.enabled) {
    c.reason = "closure off";
    return;
  }
  const Clock::time_point t0 = Clock::now();
  closure_passes_.assign(o_.speeds.size(), 0);
  run_phase_ = SweepPhase::closure;
  {
    const std::lock_guard lock(progress_mutex_);
    closure_start_ = t0;
  }
  while (!stopped_) {
    if (c.passes >= o_.closure.max_passes) {
      c.reason = "max_passes (" + std::to_string(o_.closure.max_passes) + ") passes each improved a point";
      break;
    }
    if (o_.closure.max_seconds > 0.0 && seconds_since(t0) >= o_.closure.max_seconds) {
      char text[128];
      std::snprintf(text, sizeof text, "time budget (closure.max_seconds = %g s) spent after %d passes", o_.closure.max_seconds,
                    c.passes);
      c.reason = text;
      break;
    }
    ++c.passes;
    if (!closure_pass(c.passes)) {
      c.closed = c.reason.empty();
      break;
    }
  }
  if (stopped_ && !c.closed && c.reason.empty()) c.reason = "stopped";
  c.seconds = seconds_since(t0);
  const std::lock_guard lock(progress_mutex_);
  closure_ended_ = true;
}

void Sweep::select_best() {
  r_.best.clear();
  for (std::size_t i = 0; i < o_.speeds.size(); ++i) {
    BestPoint b;
    b.speed = o_.speeds[i];
    b.seed = seed_;
    if (!closure_passes_.empty()) b.closure_passes = closure_passes_[i];
    if (const CurvePoint* p = best_at(b.speed)) {
      b.found = true;
      b.point = *p;
      b.origin = r_.origins[static_cast<std::size_t>(p->curve_id)];
      const auto pass = closure_curves_.find(p->curve_id);
      if (pass != closure_curves_.end()) b.closure_pass = pass->second;
    } else {
      const auto failure = failures_.find(i);
      b.reason = failure != failures_.end() ? failure->second : "no curve reached this speed with a KKT point";
    }
    r_.best.push_back(std::move(b));
  }
}

SpeedSweepResult Sweep::run() {
  const Clock::time_point start = Clock::now();
  const std::size_t n = o_.speeds.size();
  seeded_.assign(n, false);
  unreached_curves_.assign(n, -1);
  reached_.assign(n, false);
  progress_.speeds_total = static_cast<int>(n);
  std::vector<std::size_t> seeds;  // distinct grid indices nearest to the seed speeds
  for (double s : o_.seed_speeds) {
    const std::size_t i = static_cast<std::size_t>(
        std::min_element(o_.speeds.begin(), o_.speeds.end(), [s](double a, double b) { return std::abs(a - s) < std::abs(b - s); }) -
        o_.speeds.begin());
    if (std::find(seeds.begin(), seeds.end(), i) == seeds.end()) seeds.push_back(i);
  }
  seed_batches_left_ = static_cast<int>(seeds.size());
  for (const KnownGait& known : o_.known_gaits) {
    if (stopped_ || !curves_left()) break;
    char detail[48];
    std::snprintf(detail, sizeof detail, "from a known gait at %.4g m/s", known.speed);
    begin_phase(SweepPhase::multistart, detail, 1);
    const walker::GaitProblem shape(model_, at_speed(known.speed));
    continue_new_optimum(known.speed, best_optimum(solve_from(known.speed, {shape.initial_point(known.x)})),
                         SweepStep::known_gait);
  }
  for (const std::size_t i : seeds) {
    if (stopped_ || !curves_left()) break;
    const double v = o_.speeds[i];
    seeded_[i] = true;
    --seed_batches_left_;
    char detail[32];
    std::snprintf(detail, sizeof detail, "at %.4g m/s", v);
    begin_phase(SweepPhase::multistart, detail, o_.starts);
    const nlp::MultistartResult m = gait_multistart_at(v);
    continue_new_optimum(v, best_optimum(m), SweepStep::seed_multistart);
    continue_runner_ups(v, m);
  }
  select_best();
  if (o_.recover && !stopped_) {
    const Clock::time_point recovery_start = Clock::now();
    run_phase_ = SweepPhase::recovery;
    while (!stopped_) {
      const std::optional<Target> target = next_target();
      if (!target) break;
      recover(*target);
      select_best();
    }
    r_.recovery_seconds = seconds_since(recovery_start);
  }
  if (!stopped_) close_envelope();
  select_best();
  r_.searches.push_back({seed_, r_.best, r_.closure, first_curve_, r_.curves - first_curve_, seconds_since(start)});
  r_.seconds = seconds_since(start);
  return std::move(r_);
}

// A search per seed (speed_sweep.hpp), one after the other: curve ids run on, each search's
// journal keys are its own (search k's batch and run numbers + k * kSearchKeys), the envelope is the
// best point per speed over the searches.
constexpr int kSearchKeys = 1 << 20;

SweepJournal search_journal(const SweepJournal& j, int k) {
  const int offset = k * kSearchKeys;
  SweepJournal s;
  if (j.find_solve) s.find_solve = [&j, offset](int batch, int start) { return j.find_solve(batch + offset, start); };
  if (j.record_solve)
    s.record_solve = [&j, offset](int batch, int start, const nlp::SolverSummary& run) { j.record_solve(batch + offset, start, run); };
  if (j.find_run) s.find_run = [&j, offset](int run) { return j.find_run(run + offset); };
  if (j.record_run) s.record_run = [&j, offset](int run, const ContinuationResult& r) { j.record_run(run + offset, r); };
  if (j.find_run_state) s.find_run_state = [&j, offset](int run) { return j.find_run_state(run + offset); };
  if (j.record_run_state)
    s.record_run_state = [&j, offset](int run, const continuation::RunState& r) { j.record_run_state(run + offset, r); };
  return s;
}

// What search k of several shows its caller: the points, the progress with the search named, the
// caller's journal under the search's own keys.
class SearchObserver final : public SpeedSweepObserver {
 public:
  SearchObserver(SpeedSweepObserver& caller, const SweepJournal& journal, int k, int searches)
      : caller_(caller), journal_(search_journal(journal, k)),
        label_("seed " + std::to_string(k + 1) + " of " + std::to_string(searches) + ": ") {}
  bool on_point(const CurvePoint& p) override { return caller_.on_point(p); }
  void on_progress(const SweepProgress& p) override {
    SweepProgress q = p;
    q.detail = label_ + p.detail;
    caller_.on_progress(q);
  }
  SweepJournal journal() override { return journal_; }
  const std::string& label() const { return label_; }

 private:
  SpeedSweepObserver& caller_;
  const SweepJournal journal_;
  const std::string label_;
};

SpeedSweepResult several_searches(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                                  const SpeedSweepOptions& options, SpeedSweepObserver& observer) {
  SpeedSweepResult all;
  const SweepJournal journal = observer.journal();
  all.closure.closed = true;
  for (std::size_t k = 0; k < options.seeds.size() && !all.stopped; ++k) {  // a stop ends the later searches too
    SearchObserver search(observer, journal, static_cast<int>(k), static_cast<int>(options.seeds.size()));
    SpeedSweepResult r = Sweep(model, problem, options, search, options.seeds[k], all.curves).run();
    all.stopped = r.stopped;
    for (ContinuationResult& run : r.runs) all.runs.push_back(std::move(run));
    for (RecoveryAttempt& a : r.recoveries) all.recoveries.push_back(std::move(a));
    all.origins.insert(all.origins.end(), r.origins.begin() + all.curves, r.origins.end());
    all.curves = r.curves;
    all.multistart_solves += r.multistart_solves;
    all.resumed_solves += r.resumed_solves;
    all.computed_runs += r.computed_runs;
    all.resumed_runs += r.resumed_runs;
    all.multistart_seconds += r.multistart_seconds;
    all.multistart_cpu_seconds += r.multistart_cpu_seconds;
    all.recovery_seconds += r.recovery_seconds;
    all.seconds += r.seconds;
    all.closure.passes += r.closure.passes;
    all.closure.solves += r.closure.solves;
    all.closure.seconds += r.closure.seconds;
    if (!r.closure.closed && all.closure.closed) {
      all.closure.closed = false;
      all.closure.reason = search.label() + r.closure.reason;
    }
    all.searches.push_back(std::move(r.searches.front()));
  }
  const std::size_t n = options.speeds.size();
  for (std::size_t i = 0; i < n; ++i) {
    const BestPoint* best = nullptr;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    bool every = all.searches.size() == options.seeds.size();
    for (const SeedSearch& s : all.searches) {
      const BestPoint& b = s.best[i];
      if (!b.found) {
        every = false;
        continue;
      }
      lo = std::min(lo, b.point.objective);
      hi = std::max(hi, b.point.objective);
      if (!best || b.point.objective < best->point.objective) best = &b;
    }
    all.best.push_back(best ? *best : all.searches.front().best[i]);
    all.seed_spread.push_back(every && lo > 0.0 ? (hi - lo) / lo : std::numeric_limits<double>::quiet_NaN());
  }
  return all;
}

}  // namespace

const char* to_string(SweepPhase phase) {
  switch (phase) {
    case SweepPhase::multistart: return "multistart";
    case SweepPhase::continuation: return "continuation";
    case SweepPhase::recovery: return "recovery";
    case SweepPhase::closure: return "closure";
  }
  return "?";
}

const char* to_string(SweepStep step) {
  switch (step) {
    case SweepStep::seed_multistart: return "multistart at a seed speed";
    case SweepStep::known_gait: return "solve from a known gait";
    case SweepStep::jump: return "jump of a continuation run";
    case SweepStep::neighbour_start: return "R1 neighbour start";
    case SweepStep::neighbour_multistart: return "R2 neighbour multistart";
    case SweepStep::gait_multistart: return "R3 gait multistart";
    case SweepStep::closure: return "closure start";
  }
  return "?";
}

std::string describe(const BestPoint& best) {
  if (!best.found) return best.reason;
  char at[64];
  std::snprintf(at, sizeof at, " at %.4g m/s", best.origin.speed);
  std::string text = std::string(to_string(best.origin.step)) + at;
  if (best.closure_pass > 0) text += " in pass " + std::to_string(best.closure_pass);
  return text + (same_speed(best.point.parameter, best.origin.speed) ? "" : ", continued");
}

std::string describe(const EnvelopeClosure& closure) {
  if (closure.closed)
    return "closed after " + std::to_string(closure.passes) + (closure.passes == 1 ? " pass" : " passes");
  return "not closed: " + closure.reason;
}

SpeedSweepResult speed_sweep(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                             const SpeedSweepOptions& options, SpeedSweepObserver& observer) {
  validate(options.continuation);
  if (options.speeds.size() < 2 || !std::is_sorted(options.speeds.begin(), options.speeds.end()) ||
      std::adjacent_find(options.speeds.begin(), options.speeds.end()) != options.speeds.end())
    throw std::invalid_argument("speeds: need at least two strictly ascending values");
  if (options.seed_speeds.empty()) throw std::invalid_argument("seed_speeds: need at least one speed");
  if (options.starts < 1) throw std::invalid_argument("starts: must be >= 1");
  if (options.dominance_starts < 0) throw std::invalid_argument("dominance_starts: must be >= 0 (0: starts)");
  if (options.max_curves < 1) throw std::invalid_argument("max_curves: must be >= 1");
  if (options.runner_ups < 0) throw std::invalid_argument("runner_ups: must be >= 0 (0: the best optimum only)");
  if (!(options.runner_up_margin >= 0.0)) throw std::invalid_argument("runner_up_margin: must be >= 0");
  if (options.corrector_max_iterations < 1) throw std::invalid_argument("corrector_max_iterations: must be >= 1");
  if (options.coarse_points < 0) throw std::invalid_argument("coarse_points: must be >= 0 (0: off)");
  const int gait_count = walker::GaitProblem(model, problem).gait_parameter_count();
  for (const KnownGait& known : options.known_gaits) {
    if (std::none_of(options.speeds.begin(), options.speeds.end(), [&](double v) { return same_speed(known.speed, v); }))
      throw std::invalid_argument("known_gaits: speed " + std::to_string(known.speed) + " m/s is not one of the speeds");
    if (known.x.size() != gait_count)
      throw std::invalid_argument("known_gaits: " + std::to_string(known.x.size()) + " gait parameters, expected " +
                                  std::to_string(gait_count));
  }
  if (options.seeds.empty()) throw std::invalid_argument("seeds: need at least one seed");
  if (std::set<std::uint64_t>(options.seeds.begin(), options.seeds.end()).size() != options.seeds.size())
    throw std::invalid_argument("seeds: must be distinct");
  if (options.closure.max_passes < 1) throw std::invalid_argument("closure.max_passes: must be >= 1");
  if (!(options.closure.min_improvement >= 0.0)) throw std::invalid_argument("closure.min_improvement: must be >= 0");
  if (!(options.closure.max_seconds >= 0.0)) throw std::invalid_argument("closure.max_seconds: must be >= 0 (0: none)");
  if (options.seeds.size() == 1) {
    SpeedSweepResult r = Sweep(model, problem, options, observer, options.seeds.front(), 0).run();
    r.seed_spread.assign(r.best.size(), std::numeric_limits<double>::quiet_NaN());
    return r;
  }
  return several_searches(model, problem, options, observer);
}

SpeedSweepResult speed_sweep(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                             const SpeedSweepOptions& options, const PointCallback& on_point) {
  PointObserver observer(on_point);
  return speed_sweep(model, problem, options, observer);
}

}  // namespace cyclopt::studies
