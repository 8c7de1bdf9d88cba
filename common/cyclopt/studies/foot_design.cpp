#include "cyclopt/studies/foot_design.hpp"

#include "cyclopt/foot/convexity_constraints.hpp"
#include "cyclopt/foot/fitted_feet.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/nlp/multistart.hpp"
#include "cyclopt/nlp/solve.hpp"
#include "cyclopt/nlp/spare_core.hpp"
#include "cyclopt/nlp/wall_clock.hpp"
#include "cyclopt/studies/walker_family.hpp"
#include "cyclopt/walker/distant_start_solver.hpp"
#include "cyclopt/walker/model_parameters.hpp"
#include "cyclopt/walker/starting_gait.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <future>
#include <limits>
#include <mutex>
#include <optional>
#include <random>
#include <stdexcept>

namespace cyclopt::studies {
namespace {

using nlp::Clock;
using nlp::seconds_since;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Restarts of a design run that stopped short of a KKT point (nlp::MultistartOptions::restarts).
// rho 10, 8 starts from P2-shoes HMT with drawn feet (foot_scale 1): 1/8 runs KKT without, 3/8
// with 2 (best f_mech 0.02282 instead of 0.02405 at 2.3 m/s), in 130 s instead of 100 s.
constexpr int kDesignRestarts = 2;
// ... only of a run that ended nearly feasible (nlp::MultistartOptions::restart_max_violation).
// rho 10, 20 starts (bench/results/foot_design_bench.txt): the three runs a restart took to a KKT
// point (the design among them) ended their first solve at violations 2.3e-5, 2.5e-7 and 3.5e-5;
// start 6 stalled at 0.4 - in the elastic QPs (6.13)/(6.14), 0.3-0.6 s per iteration - and its two
// restarts took 115 of its 273.5 s without coming closer (158.0 s without them).
constexpr double kDesignRestartMaxViolation = 1e-3;
// Iterations of one design multistart solve (each restart has as many again). With the corners held
// (default_design_parameters), rho 10, 8 starts: the runs reaching the best optima (0.02256,
// 0.02637) took 320 and 571 iterations, two runs that reached none took 6000 and 5505 (232 s and
// 228 s of the multistart's 376 s) at the corrector's 2000; runs past 1000 reached only poor optima.
// 20 starts: 462 s instead of 633 s, the same 12 KKT runs and 9 optima.
constexpr int kDesignMaxIterations = 1000;


std::string rho_text(double rho) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "rho %.4g", rho);
  return buf;
}

std::string speed_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g m/s", v);
  return buf;
}

// The study's sweep options; known: gaits of the swept foot solved already (the design's, seeding
// its fixed-foot sweep), if any.
SpeedSweepOptions sweep_options(const FootDesignOptions& o, std::vector<KnownGait> known = {}) {
  SpeedSweepOptions so = o.sweep;
  so.known_gaits = std::move(known);
  return so;
}

// What a fixed-foot sweep of the study shows the study's observer: its progress (unless `quiet`)
// and the journal of its part.
class PartObserver final : public SpeedSweepObserver {
 public:
  PartObserver(FootDesignObserver& study, std::string part, bool quiet = false)
      : study_(study), part_(std::move(part)), quiet_(quiet) {}
  void on_progress(const SweepProgress& p) override {
    if (!quiet_) study_.on_sweep_progress(p);
  }
  SweepJournal journal() override { return study_.journal(part_); }

 private:
  FootDesignObserver& study_;
  const std::string part_;
  const bool quiet_;
};

// Curvature parameters at or below this are sharp corners (the seed's designs: k_H = k_T = 1e-8,
// Table 10.1).
constexpr double kCornerCurvature = 1e-6;

// The parameters the free-foot continuation (step 2) frees: the design's, but its sharp corners.
// f depends on a corner's k about like log k (at the rho 10 design, 2.3 m/s: df/dk_T = -86 at
// k_T = 3e-12, -0.37 at 2.3e-9; k df/dk ~ 1e-9), so the SQP's KKT test in k never settles: from
// that design no corrector converged within 300 iterations even 0.002 m/s away; with k_H and k_T
// fixed at the design's values in 4 (2.298 m/s), 17 (2.2) and 43 (2.0) iterations.
std::vector<std::string> free_foot_parameters(const walker::WalkerModel<double>& design, const std::vector<std::string>& free) {
  const auto layout = foot::parameter_layout(design.foot_model);
  std::vector<std::string> moving;
  for (const std::string& name : free) {
    const auto at = std::find_if(layout.begin(), layout.end(), [&](const foot::ParameterInfo& i) { return i.name == name; });
    const bool corner = at != layout.end() && at->kind == foot::ParameterKind::regularisation &&
                        design.foot_parameters[at - layout.begin()] <= kCornerCurvature;
    if (!corner) moving.push_back(name);
  }
  return moving;
}

// The converged point of `r` at the lowest parameter, nullptr if none.
const CurvePoint* lowest_converged(const ContinuationResult& r) {
  const CurvePoint* lowest = nullptr;
  for (const CurvePoint& p : r.points)
    if (p.converged && (!lowest || p.parameter < lowest->parameter)) lowest = &p;
  return lowest;
}

// The free-foot curve's last resort (step 2): a solve at each of `speeds` (descending), each from
// the last converged point, by the distant-start solver - W_1 of (6.24) on differences, where the
// continuation's corrector keeps the predictor's W - with up to kDesignRestarts restarts, down to
// the first speed without a KKT point. From the rho 10 design (corners fixed) they converge at 1.2,
// 1.1 and 1.0 m/s in 128-208 iterations and stop at MaxIter at 0.9 m/s (the seed: the free-foot
// problem converges worse below 1 m/s). Until this version a speed without a KKT point was skipped
// and only two in a row ended the solves; in the 33 free-foot continuations of
// bench/results/foot_design_bench.txt (densities 10-70) no speed after a skipped one converged (an
// older corrector had once reached 1.0 m/s after failing at 1.1), and the second failure cost the
// rho 10 study 21 s of its critical path.
ContinuationResult warm_started_solves(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                                       const CurvePoint& from, const std::vector<double>& speeds,
                                       const nlp::SolverOptions& corrector) {
  const Clock::time_point t0 = Clock::now();
  ContinuationResult r;
  r.next_curve_id = from.curve_id + 1;
  const nlp::SolverOptions solver = walker::distant_start_solver(corrector, 0);
  Eigen::VectorXd x = from.x;
  r.finished = true;
  for (double v : speeds) {
    walker::GaitProblemOptions at = problem;
    at.speed = v;
    walker::GaitProblem problem_at(model, at);
    const nlp::SolverSummary s = nlp::solve_with_restarts(problem_at, solver, x, kDesignRestarts);
    if (s.termination == nlp::Termination::user_stop) {
      r.finished = false;
      r.message = "stopped";
      break;
    }
    CurvePoint p;
    p.parameter = v;
    p.curve_id = from.curve_id;
    p.on_grid = true;
    p.converged = s.success();
    p.x = s.x;
    p.objective = s.objective;
    p.corrector = s;
    p.seconds = s.wall_seconds;
    r.points.push_back(p);
    r.corrector_iterations += s.iterations;
    if (!p.converged) {
      r.finished = false;
      r.message = "no KKT point at " + speed_text(v) + " from the last converged point: " + s.message;
      break;
    }
    x = s.x;
  }
  if (r.finished) r.message = "reached the last parameter value";
  r.seconds = seconds_since(t0);
  return r;
}

// Saving of `foot` against `reference` (foot_comparison.hpp), NaN without a reference sweep.
double saving(const std::vector<double>& speeds, const FootSweepSummary& reference, const FootSweepSummary& foot) {
  if (reference.f_mech.empty() || foot.f_mech.empty()) return kNaN;
  return summarise_feet(speeds, {reference, foot}, 0).feet[1].saving;
}

// f, called one call at a time under `m` (an empty f stays empty).
template <class R, class... A>
std::function<R(A...)> one_at_a_time(std::function<R(A...)> f, std::mutex& m) {
  if (!f) return f;
  return [f = std::move(f), &m](A... a) -> R {
    const std::lock_guard lock(m);
    return f(a...);
  };
}

// The caller's observer for a study that runs on two threads (the design's fixed-foot sweep beside
// step 2 and the low-speed sweep, DesignStudy::at): every call takes `m`, so the caller sees one
// call at a time, as from one thread.
class OneAtATime final : public FootDesignObserver {
 public:
  OneAtATime(FootDesignObserver& caller, std::mutex& m) : caller_(caller), m_(m) {}
  bool on_step(const std::string& step) override {
    const std::lock_guard lock(m_);
    return caller_.on_step(step);
  }
  bool on_reference(const std::string& part, const walker::WalkerModel<double>& model, const FootSweepSummary& sweep) override {
    const std::lock_guard lock(m_);
    return caller_.on_reference(part, model, sweep);
  }
  bool on_density(const DensityDesign& so_far, DesignPhase finished) override {
    const std::lock_guard lock(m_);
    return caller_.on_density(so_far, finished);
  }
  void on_multistart_progress(double density, int runs_done, double best) override {
    const std::lock_guard lock(m_);
    caller_.on_multistart_progress(density, runs_done, best);
  }
  void on_sweep_progress(const SweepProgress& progress) override {
    const std::lock_guard lock(m_);
    caller_.on_sweep_progress(progress);
  }
  SweepJournal journal(const std::string& part) override {
    SweepJournal j;
    {
      const std::lock_guard lock(m_);
      j = caller_.journal(part);
    }
    j.record_solve = one_at_a_time(j.record_solve, m_);
    j.record_run = one_at_a_time(j.record_run, m_);
    j.record_run_state = one_at_a_time(j.record_run_state, m_);
    return j;
  }

 private:
  FootDesignObserver& caller_;
  std::mutex& m_;
};

// The options with the corrector's on_iteration called under `m`, as the observer is (OneAtATime).
// The corrector's should_stop is polled from any thread already.
FootDesignOptions one_at_a_time(const FootDesignOptions& o, std::mutex& m) {
  FootDesignOptions s = o;
  s.sweep.continuation.corrector.on_iteration = one_at_a_time(o.sweep.continuation.corrector.on_iteration, m);
  return s;
}

class DesignStudy {
 public:
  DesignStudy(const foot::FootSpec& start, const walker::GaitProblemOptions& problem, const FootDesignOptions& o,
              FootDesignObserver& observer, std::vector<std::string> free)
      : observer_(observer, callbacks_), start_(start), problem_(problem), o_(one_at_a_time(o, callbacks_)),
        free_(std::move(free)) {}

  DensityDesign at(double rho);

 private:
  bool step(const std::string& text) { return observer_.on_step(text); }
  bool finished(const DensityDesign& d, DesignPhase phase) { return observer_.on_density(d, phase); }
  walker::WalkerModel<double> model_of(const foot::FootSpec& foot) const { return walker::make_walker_model(foot, o_.constants); }
  DesignOptimum optimum(const walker::GaitProblem& shape, double rho, const nlp::MultistartOptimum& m,
                        const std::vector<nlp::SolverSummary>& runs) const;
  Eigen::VectorXd design_start(const foot::FootSpec& start, const walker::GaitProblemOptions& po,
                               const Eigen::VectorXd& centre, std::mt19937_64& rng) const;
  walker::GaitProblemOptions free_problem(double speed) const {
    walker::GaitProblemOptions po = problem_;
    po.speed = speed;
    po.free_parameters = free_;
    po.design_bounds = o_.bounds;
    return po;
  }

  std::mutex callbacks_;  // the observer and o_'s callbacks: one call at a time from the study's two threads
  OneAtATime observer_;
  const foot::FootSpec& start_;
  const walker::GaitProblemOptions& problem_;
  const FootDesignOptions o_;
  const std::vector<std::string> free_;
};

DesignOptimum DesignStudy::optimum(const walker::GaitProblem& shape, double rho, const nlp::MultistartOptimum& m,
                                   const std::vector<nlp::SolverSummary>& runs) const {
  DesignOptimum d;
  d.objective = m.objective;
  d.z = m.x;
  d.starts = m.starts;
  for (int i : m.starts)  // the best run that reached it, whose x it is
    if (d.summary.x.size() == 0 || runs[static_cast<std::size_t>(i)].objective < d.summary.objective)
      d.summary = runs[static_cast<std::size_t>(i)];
  const walker::WalkerModel<double> designed = shape.model_at(m.x);
  d.foot = start_;
  d.foot.parameters = designed.foot_parameters;
  d.foot.density = rho;
  d.foot.theta_F0.reset();  // follows the geometry (E.7)
  d.mass = designed.segments[walker::m_F];
  d.com_distance = designed.segments[walker::r_F];
  d.inertia = designed.segments[walker::J_F];
  d.zero_angle = designed.foot_zero_angle;
  const foot::LinearInequalities rows = foot::design_constraints(designed.foot_model, o_.bounds);
  const Eigen::VectorXd margin = rows.A * designed.foot_parameters + rows.b;
  for (Eigen::Index i = 0; i < margin.size(); ++i)
    if (margin(i) <= 1e-6) d.active_bounds.push_back(rows.names[static_cast<std::size_t>(i)]);
  const walker::PeriodicGait<double> gait = shape.gait_at(m.x);
  if (gait.real)
    d.classification = classify_design(designed, gait, shape.refined_objective(m.x, kResolutionFactor),
                                       o_.resolution_tolerance);
  else
    d.classification = {DesignClass::stilt, "the gait has no real periodic solution at the optimum: " + gait.failure};
  return d;
}

// z of one design start: a foot drawn around the start foot and the start foot's starting gait
// perturbed until that foot walks it (a real periodic solution); after 10 feet without one, the
// start foot itself.
Eigen::VectorXd DesignStudy::design_start(const foot::FootSpec& start, const walker::GaitProblemOptions& po,
                                          const Eigen::VectorXd& centre, std::mt19937_64& rng) const {
  for (int draw = 0; draw < 10 && o_.foot_scale > 0.0; ++draw) {
    foot::FootSpec drawn = start;
    drawn.parameters = draw_design_foot(start, free_, o_.bounds, o_.foot_scale, rng);
    const walker::WalkerModel<double> m = model_of(drawn);
    try {
      const Eigen::VectorXd x = walker::perturbed_gait(walker::GaitEvaluator(m), centre, o_.scale, rng, 100);
      return walker::GaitProblem(m, po).initial_point(x);
    } catch (const std::runtime_error&) {
      // this foot does not walk near the start gait: draw another
    }
  }
  const walker::WalkerModel<double> m = model_of(start);
  return walker::GaitProblem(m, po).initial_point(walker::perturbed_gait(walker::GaitEvaluator(m), centre, o_.scale, rng));
}

DensityDesign DesignStudy::at(double rho) {
  const Clock::time_point t0 = Clock::now();
  DensityDesign d;
  d.density = rho;
  d.free_foot_f_mech.assign(o_.sweep.speeds.size(), kNaN);
  d.saving_vs_start = d.saving_vs_point = d.low_saving_vs_start = d.low_saving_vs_point = kNaN;
  const std::string name = rho_text(rho);

  // 1. Design multistart at the design speed.
  if (!step(name + ": design multistart at " + speed_text(o_.design_speed))) return d.stopped = true, d;
  foot::FootSpec start = start_;
  start.density = rho;
  start.theta_F0.reset();
  start.parameters = foot::project_into_design_bounds(start.model, start.parameters, o_.bounds, free_);
  const walker::WalkerModel<double> model = model_of(start);
  const walker::GaitProblemOptions po = free_problem(o_.design_speed);
  d.model = model;
  d.problem = po;
  const SweepJournal journal = observer_.journal(name + "/design");
  const walker::GaitEvaluator ev(model);
  const Eigen::VectorXd centre = walker::gait_start(ev, o_.design_speed, {}).x;
  const walker::GaitProblem shape(model, po);
  nlp::MultistartOptions mo;
  // No Hessian refresh: it stopped tests/service/test_foot_design_jobs' design start (P = 50, seed 2)
  // short of the KKT point W_1 alone reaches in 489 of 500 iterations, and with drawn feet (rho 10,
  // 8 starts, foot_scale 1) no run reached a KKT point with it (1/8 without).
  mo.solver = walker::distant_start_solver(o_.sweep.continuation.corrector, 0);
  mo.solver.max_iterations = std::min(mo.solver.max_iterations, kDesignMaxIterations);
  // A run without progress over kMultistartProgressWindow iterations ends as stalled and is
  // restarted like one at MaxIter (fresh W_1): rho 10, 20 starts (bench/results/foot_design_bench.txt
  // run H) the same 11 KKT runs and optima, 248 s instead of 316 s.
  mo.solver.sqp.progress_window = walker::kMultistartProgressWindow;
  mo.objective_tolerance = o_.objective_tolerance;
  mo.restarts = kDesignRestarts;
  mo.restart_max_violation = kDesignRestartMaxViolation;
  // Only KKT points are designs: an "acceptable" run (a step below TolStep, a potential KKT point)
  // is restarted and left out if it stays one. rho 30 and 50 chose such designs (f 0.0110 and 0.0053
  // at 2.3 m/s, where converged designs have 0.023-0.042); neither could be continued over the speed.
  mo.acceptance = nlp::Acceptance::kkt_only;
  mo.x_tolerance = o_.x_tolerance;
  // No coarse-to-fine batches as in the sweeps (SpeedSweepOptions::coarse_points): measured at
  // rho 10 (8 starts, seed 1, foot_scale 1), P = 100 first reached 1/8 KKT points (560 s beside a
  // benchmark) where P = 200 alone reaches 3/8 (130 s idle).
  journal_multistart(mo, journal, 0);
  mo.on_progress = [&](int done, double best) { observer_.on_multistart_progress(rho, done, best); };
  // The drawn starts (start i from base_seed + i, as nlp::multistart draws them), then the known designs.
  std::vector<Eigen::VectorXd> starts;
  for (int i = 0; i < o_.starts; ++i) {
    std::mt19937_64 rng(o_.seed + static_cast<std::uint64_t>(i));
    starts.push_back(design_start(start, po, centre, rng));
  }
  for (const KnownDesign& k : o_.known_designs)
    if (k.density == rho) {
      if (k.z.size() != shape.num_variables())
        throw std::invalid_argument("known_designs: " + std::to_string(k.z.size()) + " values at " + name + ", the design problem has " +
                                    std::to_string(shape.num_variables()) + " (gait parameters, then " + std::to_string(free_.size()) +
                                    " foot parameters)");
      starts.push_back(k.z);
    }
  const nlp::MultistartResult r = nlp::multistart_from([&] { return std::make_unique<walker::GaitProblem>(model, po); },
                                                       std::move(starts), mo);
  d.kkt_starts = r.successes;
  for (const nlp::SolverSummary& run : r.runs)
    d.runs.push_back({run.termination, run.iterations, run.function_evaluations + run.jacobian_evaluations, run.wall_seconds,
                      run.objective});
  for (const nlp::MultistartOptimum& m : r.optima) {
    d.optima.push_back(optimum(shape, rho, m, r.runs));
    const DesignClass c = d.optima.back().classification.design_class;
    ++d.class_counts[static_cast<int>(c)];
    if (d.best < 0 && c == DesignClass::admissible) d.best = static_cast<int>(d.optima.size()) - 1;
  }
  d.multistart_seconds = seconds_since(t0);
  if (d.best < 0) d.seconds = seconds_since(t0);
  if (!finished(d, DesignPhase::multistart)) return d.stopped = true, d;
  if (d.best < 0) return d;
  const DesignOptimum& best = d.optima[static_cast<std::size_t>(d.best)];

  // 3a. The fixed-foot sweep of the design, on a thread of its own beside steps 2 and 3b: it needs
  // only the design, and steps 2 and 3b leave a core idle while they continue (one thread) - run E
  // of bench/results/foot_design_bench.txt: 155 % CPU over the study. Each sweep starts from its
  // foot's own optimal gait (the free-foot optimum is a KKT point of the fixed-foot problem too),
  // then adds the seed multistarts: without it the sweep of the rho 10 design reached f_mech
  // 0.0413 at 2.3 m/s where the design has 0.0344. Its progress is not reported (step 2's and
  // 3b's are); its solves still count iterations and stop with the study.
  const Clock::time_point t1 = Clock::now();
  if (!step(name + ": free-foot continuation, the design's fixed-foot sweep beside it")) return d.stopped = true, d;
  const int gait_count = shape.gait_parameter_count();
  std::atomic<bool> abandon_high{false};
  SpeedSweepOptions high_options = sweep_options(o_, {{o_.design_speed, best.z.head(gait_count)}});
  high_options.continuation.corrector.should_stop = [&abandon_high, stop = high_options.continuation.corrector.should_stop] {
    return abandon_high.load() || (stop && stop());
  };
  // Step 2 and the low-speed design's sweep after it are the study's critical path: the design's
  // sweep takes the cores they leave idle (nlp::lower_thread_priority). rho 10, 20 starts
  // (bench/results/foot_design_bench.txt): step 2 55.0 s instead of 67.5 s, the study 567.1 s
  // instead of 603.9 s, the design's sweep 274.7 s instead of 190.7 s beside them; same results.
  std::future<FootSweepSummary> high = std::async(std::launch::async, [&, high_options] {
    nlp::lower_thread_priority();
    PartObserver high_observer(observer_, name + "/high", true);
    return sweep_foot(name + " design", model_of(best.foot), problem_, high_options, high_observer);
  });
  // Whichever way this function leaves, the design's sweep has ended before its locals go.
  const struct JoinHigh {
    std::atomic<bool>& abandon;
    std::future<FootSweepSummary>& sweep;
    ~JoinHigh() {
      if (!sweep.valid()) return;
      abandon = true;
      sweep.wait();
    }
  } join_high{abandon_high, high};

  // 2. Free-foot continuation downwards from the design speed.
  std::vector<double> grid{o_.design_speed};
  for (auto it = o_.sweep.speeds.rbegin(); it != o_.sweep.speeds.rend(); ++it)
    if (*it < o_.design_speed - 1e-12) grid.push_back(*it);
  d.low_speed_foot = best.foot;
  d.low_speed = o_.design_speed;
  Eigen::VectorXd low_speed_gait = best.z.head(gait_count);
  if (grid.size() >= 2) {
    ContinuationOptions co = o_.sweep.continuation;
    co.corrector.max_iterations = std::min(co.corrector.max_iterations, o_.sweep.corrector_max_iterations);
    // The design's foot with its sharp corners fixed (free_foot_parameters), and the design's gait.
    d.free_foot_model = shape.model_at(best.z);
    d.free_foot_problem = po;
    d.free_foot_problem.free_parameters = free_foot_parameters(d.free_foot_model, free_);
    const walker::GaitProblem free_foot(d.free_foot_model, d.free_foot_problem);
    const Eigen::VectorXd z0 = free_foot.initial_point(best.z.head(gait_count));
    const ParametricProblem family = walker_family(d.free_foot_model, d.free_foot_problem, "speed");
    // Run n of the journal (unless recorded in another layout, by a version that freed every
    // parameter), or computed (and recorded unless the job stopped it).
    const auto journaled_run = [&](int n, const std::function<ContinuationResult()>& compute) {
      std::optional<ContinuationResult> recorded = journal.find_run ? journal.find_run(n) : std::nullopt;
      if (recorded && !recorded->points.empty() && recorded->points.front().x.size() == z0.size())
        return std::move(*recorded);
      ContinuationResult computed = compute();
      if (computed.message != "stopped" && journal.record_run) journal.record_run(n, computed);
      return computed;
    };
    const auto run = [&](int n, const Eigen::VectorXd& x0, const std::vector<double>& values,
                         const ContinuationOptions& options) {
      return journaled_run(n, [&] { return continue_solution(family, x0, values, options); });
    };
    d.free_foot = run(0, z0, grid, co);
    // The free-foot problem converges worse than the fixed-foot one (section 10.2, below 1 m/s):
    // where the QPSQP run stopped, warm-started solves at the grid speeds below
    // (warm_started_solves) from its lowest converged point. From the rho 10 design they reached
    // 1.0 m/s where the run stopped at 1.2145 m/s. (A run with the trivial predictor from that
    // point, tried first until this version - journal run 1 -, ended where the QPSQP run had, without
    // a converged point, in all 29 free-foot continuations of bench/results/foot_design_bench.txt
    // (densities 10-70): 11 s of the rho 10 study's critical path.)
    if (const CurvePoint* lowest = lowest_converged(d.free_foot); !d.free_foot.finished && lowest) {
      std::vector<double> rest;
      for (double v : grid)
        if (v < lowest->parameter - 1e-12) rest.push_back(v);
      if (!rest.empty()) {
        const CurvePoint from = *lowest;
        ContinuationResult more = journaled_run(2, [&] {
          return warm_started_solves(d.free_foot_model, d.free_foot_problem, from, rest, co.corrector);
        });
        d.free_foot.message += "; then warm-started solves: " + more.message;
        d.free_foot.finished = more.finished;
        d.free_foot.points.insert(d.free_foot.points.end(), more.points.begin(), more.points.end());
      }
    }
    for (const CurvePoint& p : d.free_foot.points) {
      if (!p.converged) continue;
      walker::GaitProblemOptions at_speed = d.free_foot_problem;
      at_speed.speed = p.parameter;
      const walker::GaitProblem at(d.free_foot_model, at_speed);
      const walker::PeriodicGait<double> g = at.gait_at(p.x);
      for (std::size_t i = 0; i < o_.sweep.speeds.size(); ++i)
        if (std::abs(o_.sweep.speeds[i] - p.parameter) <= 1e-12 && g.real) d.free_foot_f_mech[i] = g.f_mech;
      if (p.on_grid && p.parameter < d.low_speed) {
        d.low_speed = p.parameter;
        d.low_speed_foot.parameters = at.model_at(p.x).foot_parameters;
        low_speed_gait = p.x.head(gait_count);
      }
    }
  }
  d.continuation_seconds = seconds_since(t1);
  if (!finished(d, DesignPhase::free_foot)) return d.stopped = true, d;

  // 3b. The fixed-foot sweep of the foot optimal at the lowest speed, then the design's (3a) joined.
  // Where step 2 reached no grid speed below the design speed, that foot and its known gait are the
  // design's, so its sweep is the design's: the density list's rho 30 (bench/results/
  // foot_design_bench.txt) otherwise swept the same foot twice at once, 2443 s each.
  const Clock::time_point t2 = Clock::now();
  const bool low_is_design = !(d.low_speed < o_.design_speed);
  if (!low_is_design) {
    if (!step(name + ": fixed-foot sweep of the low-speed design")) return d.stopped = true, d;
    PartObserver low_observer(observer_, name + "/low");
    d.low = sweep_foot(name + " low-speed design", model_of(d.low_speed_foot), problem_,
                       sweep_options(o_, {{d.low_speed, low_speed_gait}}), low_observer);
  }
  if (high.wait_for(std::chrono::seconds(0)) != std::future_status::ready &&
      !step(name + (low_is_design ? ": fixed-foot sweep of the design (also the low-speed design: step 2 reached no lower speed)"
                                  : ": fixed-foot sweep of the design (the low-speed design's has ended)")))
    return d.stopped = true, d;
  d.high = high.get();  // rethrows what the design's sweep threw
  if (low_is_design) {
    d.low = d.high;
    d.low.name = name + " low-speed design";
    d.low.seconds = 0.0;  // not swept again
  }
  d.sweep_seconds = seconds_since(t2);
  d.seconds = seconds_since(t0);
  if (!finished(d, DesignPhase::high_sweep) || !finished(d, DesignPhase::low_sweep)) d.stopped = true;
  return d;
}

}  // namespace

foot::FootParameters<double> draw_design_foot(const foot::FootSpec& start, const std::vector<std::string>& free,
                                            const foot::DesignBounds& bounds, double scale, std::mt19937_64& rng) {
  const auto layout = foot::parameter_layout(start.model);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int draw = 0; draw < 100; ++draw) {
    foot::FootSpec drawn = start;
    foot::FootParameters<double>& p = drawn.parameters;
    for (std::size_t k = 0; k < layout.size(); ++k)
      if (std::find(free.begin(), free.end(), layout[k].name) != free.end()) {
        const auto i = static_cast<Eigen::Index>(k);
        p[i] = std::clamp(p[i] * std::exp(scale * normal(rng)), layout[k].min, layout[k].max);
      }
    p = foot::project_into_design_bounds(start.model, p, bounds, free);
    if (foot::admissibility_violations(drawn).empty()) return p;  // convex (3.24, toe) and in range
  }
  return start.parameters;
}

std::vector<std::string> default_design_parameters(foot::FootModel model) {
  const std::array<int, 2> corners = model == foot::FootModel::hm ? std::array<int, 2>{foot::hm::k_H, foot::hm::k_M}
                                                                  : std::array<int, 2>{foot::hmt::k_H, foot::hmt::k_T};
  const auto layout = foot::parameter_layout(model);
  std::vector<std::string> free;
  for (std::size_t i = 0; i < layout.size(); ++i)
    if (std::find(corners.begin(), corners.end(), static_cast<int>(i)) == corners.end()) free.emplace_back(layout[i].name);
  return free;
}

std::vector<std::string> design_free_parameters(const foot::FootSpec& start, const FootDesignOptions& o) {
  if (start.model == foot::FootModel::point) throw std::invalid_argument("foot: the start foot must be HM or HMT");
  if (o.densities.empty()) throw std::invalid_argument("densities: need at least one density");
  for (double rho : o.densities)
    if (!(rho > 0.0) || !std::isfinite(rho)) throw std::invalid_argument("densities: each must be > 0 kg/m^2");
  if (o.starts < 1) throw std::invalid_argument("starts: must be >= 1");
  if (!(o.foot_scale >= 0.0 && o.foot_scale <= 3.0)) throw std::invalid_argument("foot_scale: must be in [0, 3]");
  if (!(o.resolution_tolerance > 0.0)) throw std::invalid_argument("resolution_tolerance: must be > 0");
  for (const KnownDesign& k : o.known_designs)
    if (std::find(o.densities.begin(), o.densities.end(), k.density) == o.densities.end())
      throw std::invalid_argument("known_designs: density " + std::to_string(k.density) + " kg/m^2 is not one of the densities");
  if (std::none_of(o.sweep.speeds.begin(), o.sweep.speeds.end(), [&](double v) { return std::abs(v - o.design_speed) <= 1e-12; }))
    throw std::invalid_argument("design_speed: must be one of the speeds");
  std::vector<std::string> free = o.free_parameters;
  if (free.empty()) free = default_design_parameters(start.model);
  for (const std::string& name : free) {
    const auto layout = foot::parameter_layout(start.model);
    if (std::none_of(layout.begin(), layout.end(), [&](const foot::ParameterInfo& i) { return name == i.name; }))
      throw std::invalid_argument("free_parameters: '" + name + "' is not a parameter of the " +
                                  std::string(foot::to_string(start.model)) + " foot");
  }
  const foot::FootParameters<double> projected = foot::project_into_design_bounds(start.model, start.parameters, o.bounds, free);
  const std::vector<std::string> violated = foot::violated_design_bounds(start.model, projected, o.bounds, 1e-12);
  if (!violated.empty())
    throw std::invalid_argument("design_bounds: the start foot violates " + violated.front() +
                                " in a parameter that is not free");
  return free;
}

const char* reference_part(DesignReference which) {
  return which == DesignReference::start_foot ? "references/start foot" : "references/point feet";
}

walker::WalkerModel<double> reference_model(DesignReference which, const foot::FootSpec& start,
                                            const walker::WalkingConstants& constants) {
  if (which == DesignReference::point_feet) return walker::make_walker_model(foot::foot_preset("point").spec, constants);
  foot::FootSpec own_masses = start;
  own_masses.density.reset();
  return walker::make_walker_model(own_masses, constants);
}

FootSweepSummary sweep_reference(DesignReference which, const foot::FootSpec& start, const walker::GaitProblemOptions& problem,
                                 const FootDesignOptions& o, FootDesignObserver& observer) {
  const std::string name = which == DesignReference::start_foot ? "start foot " + start.name : "point feet";
  PartObserver part(observer, reference_part(which));
  return sweep_foot(name, reference_model(which, start, o.constants), problem, sweep_options(o), part);
}

DensityDesign design_density(double rho, const foot::FootSpec& start, const walker::GaitProblemOptions& problem,
                             const FootDesignOptions& o, FootDesignObserver& observer) {
  return DesignStudy(start, problem, o, observer, design_free_parameters(start, o)).at(rho);
}

const char* to_string(DesignAnswer a) { return a == DesignAnswer::design ? "design" : "low-speed design"; }

DesignAnswer better_design(const FootSweepSummary& high, const FootSweepSummary& low) {
  if (low.speeds_found != high.speeds_found)
    return low.speeds_found > high.speeds_found ? DesignAnswer::low_speed_design : DesignAnswer::design;
  double high_sum = 0.0, low_sum = 0.0;
  for (std::size_t i = 0; i < high.f_mech.size() && i < low.f_mech.size(); ++i)
    if (std::isfinite(high.f_mech[i]) && std::isfinite(low.f_mech[i])) {
      high_sum += high.f_mech[i];
      low_sum += low.f_mech[i];
    }
  return low_sum < high_sum ? DesignAnswer::low_speed_design : DesignAnswer::design;
}

void add_savings(DensityDesign& d, const std::vector<double>& speeds, const FootSweepSummary& start_foot,
                 const FootSweepSummary& point_feet) {
  d.answer = better_design(d.high, d.low);
  d.saving_vs_start = saving(speeds, start_foot, d.high);
  d.saving_vs_point = saving(speeds, point_feet, d.high);
  d.low_saving_vs_start = saving(speeds, start_foot, d.low);
  d.low_saving_vs_point = saving(speeds, point_feet, d.low);
}

FootDesignResult design_feet(const foot::FootSpec& start, const walker::GaitProblemOptions& problem,
                             const FootDesignOptions& o, FootDesignObserver& observer) {
  const std::vector<std::string> free = design_free_parameters(start, o);
  const Clock::time_point t0 = Clock::now();
  FootDesignResult result;
  result.speeds = o.sweep.speeds;
  if (o.references) {
    if (!observer.on_step("references: start foot and point feet")) return result;
    for (DesignReference which : {DesignReference::start_foot, DesignReference::point_feet}) {
      FootSweepSummary& s = which == DesignReference::start_foot ? result.start_foot : result.point_feet;
      s = sweep_reference(which, start, problem, o, observer);
      if (!observer.on_reference(reference_part(which), reference_model(which, start, o.constants), s))
        return result;
    }
    result.reference_seconds = seconds_since(t0);
  }
  DesignStudy study(start, problem, o, observer, free);
  for (double rho : o.densities) {
    result.designs.push_back(study.at(rho));
    DensityDesign& d = result.designs.back();
    if (d.stopped) break;
    add_savings(d, o.sweep.speeds, result.start_foot, result.point_feet);
    const int k = static_cast<int>(result.designs.size()) - 1;
    if (std::isfinite(d.answer_saving_vs_start()) &&
        (result.best_design < 0 ||
         d.answer_saving_vs_start() > result.designs[static_cast<std::size_t>(result.best_design)].answer_saving_vs_start()))
      result.best_design = k;
  }
  result.seconds = seconds_since(t0);
  return result;
}

}  // namespace cyclopt::studies
