#include "cyclopt/continuation/continuation_solver.hpp"

#include "cyclopt/continuation/curve_jump.hpp"
#include "cyclopt/continuation/qp_predictor.hpp"
#include "cyclopt/nlp/solve.hpp"
#include "cyclopt/nlp/wall_clock.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace cyclopt::continuation {

namespace {

using nlp::Clock;
using nlp::seconds_since;
using Eigen::MatrixXd;
using Eigen::VectorXd;

void check_parameters(const std::vector<double>& p) {
  if (p.size() < 2) throw std::invalid_argument("parameters: need p_0 and at least one further value");
  const double direction = p[1] - p[0];
  for (std::size_t i = 1; i < p.size(); ++i)
    if (!((p[i] - p[i - 1]) * direction > 0.0))
      throw std::invalid_argument("parameters: must be strictly monotone (value " + std::to_string(i) + ")");
}

class Run {
 public:
  Run(const ParametricProblem& family, const std::vector<double>& grid, const ContinuationOptions& o,
      const CurveStart& start, const PointCallback& on_point, const StateCallback& on_state)
      : family_(family), grid_(grid), o_(o), on_point_(on_point), on_state_(on_state), curve_(start.curve_id),
        next_curve_(start.next_curve_id) {
    double max_spacing = 0.0;
    for (std::size_t i = 1; i < grid.size(); ++i) max_spacing = std::max(max_spacing, std::abs(grid[i] - grid[i - 1]));
    // Table 7.1: Delta_1 = |p_2 - p_1|, Delta_max = max |p_{k+1} - p_k|.
    max_trust_ = o.max_trust_region > 0.0 ? o.max_trust_region : max_spacing;
    trust_ = std::clamp(o.initial_trust_region > 0.0 ? o.initial_trust_region : std::abs(grid[1] - grid[0]),
                        o.min_trust_region, std::max(o.min_trust_region, max_trust_));
    settings_.eta = o.eta;
    settings_.active_tolerance = o.active_tolerance;
    settings_.constraint_tolerance = o.corrector.constraint_tolerance;
    settings_.relative_min_penalty = o.corrector.sqp.relative_min_penalty;
    settings_.qp = o.corrector.sqp.qp;
    settings_.fresh_second_hessian = !o.reuse_predictor_hessian;
  }

  ContinuationResult run(const VectorXd& x0);
  ContinuationResult resume(const RunState& state);

 private:
  ContinuationResult steps(Clock::time_point start);  // steps 2-19 from x_k on
  void take_point(const CurvePoint& point) {  // a converged point the run goes on from: x_k
    x_k_ = point.x;
    f_k_ = point.objective;
    solve_k_ = point.corrector;
    p_ = point.parameter;
  }
  void report_state() const {
    if (on_state_) on_state_({result_, curve_, l_, tried_value_, secant_, trust_});
  }
  // `previous`: the corrector's solve at the last point (absent for the first point).
  // difference_start: without W, the SQP starts from W_1 of (6.24) on differences, not from I.
  nlp::SolverSummary correct(double p, const VectorXd& x_start, const std::optional<MatrixXd>& W,
                             const nlp::SolverSummary* previous, bool difference_start) const {
    nlp::SolverOptions so = o_.corrector;
    if (W && so.solver == nlp::SolverKind::sqp)  // step 19: W_{k+1,0} as the SQP's initial Hessian
      so.sqp.lagrangian_hessian = [W](const VectorXd&, const VectorXd&, const VectorXd&) { return *W; };
    if (!W && difference_start) {
      so.sqp.difference_hessian = true;
      so.ipopt.difference_hessian_start = true;
    }
    // Ipopt warm start: the last point's multipliers, and the Hessian from differences at the
    // start - from the identity Ipopt needs as many iterations as from a cold start (point feet
    // 1.3 -> 1.4 m/s: 214 iterations, with the difference Hessian 7; walker_solvers.txt).
    if (previous && so.solver == nlp::SolverKind::ipopt && !so.ipopt.warm_start) {
      so.ipopt.warm_start = nlp::IpoptWarmStart{previous->equality_multipliers, previous->inequality_multipliers,
                                                previous->bound_multipliers};
      so.ipopt.difference_hessian_start = true;
    }
    return nlp::solve(*family_.at(p), so, x_start);
  }
  bool on_grid(double p) const {
    return std::any_of(grid_.begin() + 1, grid_.end(), [p](double g) { return std::abs(p - g) <= 1e-12 * std::max(1.0, std::abs(g)); });
  }
  bool emit(CurvePoint point) {
    result_.corrector_iterations += point.corrector.iterations;
    result_.predictor_steps += point.predictor_steps;
    result_.points.push_back(std::move(point));
    return !on_point_ || on_point_(result_.points.back());
  }

  const ParametricProblem& family_;
  const std::vector<double>& grid_;
  const ContinuationOptions& o_;
  const PointCallback& on_point_;
  const StateCallback& on_state_;
  QpPredictorSettings settings_;
  ContinuationResult result_;
  int curve_, next_curve_;
  double trust_ = 0.0, max_trust_ = 0.0;
  // Where the run stands (RunState): the last converged point and the next requested value.
  VectorXd x_k_;
  double f_k_ = 0.0;
  nlp::SolverSummary solve_k_;  // at x_k
  double p_ = 0.0;
  std::size_t l_ = 1;
  std::optional<double> secant_;  // of the last step on the current curve
  std::size_t tried_value_ = 0;   // trivial_then_qp: the requested value l whose direct step was tried
};

ContinuationResult Run::run(const VectorXd& x0) {
  const Clock::time_point start = Clock::now();
  // Step 1: the first point.
  CurvePoint first;
  first.parameter = grid_[0];
  first.curve_id = curve_;
  first.on_grid = true;
  // From W_1 of (6.24) on differences: x0 is usually a KKT point of another solve (a multistart, a
  // recovery) that the SQP accepts before computing any W_1; where its own test disagrees (another
  // active set), W_1 = I needed > 300 iterations and lost the point (P2 HMT 0.3 m/s, recovery R1
  // f_mech 0.003644).
  first.corrector = correct(grid_[0], x0, std::nullopt, nullptr, true);
  first.converged = first.corrector.success();
  first.x = first.corrector.x;
  first.objective = first.corrector.objective;
  first.seconds = seconds_since(start);
  take_point(first);
  const bool first_ok = first.converged;
  if (!emit(std::move(first)) || !first_ok) {
    const bool stopped = first_ok || result_.points.back().corrector.termination == nlp::Termination::user_stop;
    result_.message = stopped ? "stopped" : "no KKT point at the first parameter value";
    result_.next_curve_id = next_curve_;
    result_.seconds = seconds_since(start);
    return std::move(result_);
  }
  result_.next_curve_id = next_curve_;
  report_state();
  return steps(start);
}

ContinuationResult Run::resume(const RunState& state) {
  const Clock::time_point start = Clock::now();
  result_ = state.result;
  curve_ = state.curve_id;
  next_curve_ = state.result.next_curve_id;
  take_point(result_.points.back());
  l_ = state.next_value;
  tried_value_ = state.tried_value;
  secant_ = state.secant;
  trust_ = state.trust_region;
  return steps(start);
}

ContinuationResult Run::steps(Clock::time_point start) {
  VectorXd& x_k = x_k_;
  double& f_k = f_k_;
  nlp::SolverSummary& solve_k = solve_k_;
  double& p = p_;
  std::size_t& l = l_;
  std::optional<double>& secant = secant_;
  std::size_t& tried_value = tried_value_;
  double trivial_step = 0.0;     // > 0: shortened after a failed corrector
  const bool uses_qp = o_.predictor != Predictor::trivial;
  const bool to_each_value = uses_qp || o_.fixed_step == 0.0;
  std::optional<MatrixXd> W1_at_k;  // reuse_predictor_hessian: the predictor's W_1 at x_k
  for (;;) {
    const Clock::time_point t0 = Clock::now();
    const double target = to_each_value ? grid_[l] : grid_.back();
    const double remaining = std::abs(target - p), direction = target > p ? 1.0 : -1.0;
    CurvePoint point;
    VectorXd x_start = x_k;
    std::optional<MatrixXd> W;
    double p_new = 0.0, step = 0.0, next_trust = trust_;  // step = |Delta p| exactly (p_new - p may round)
    // trivial_then_qp: once per requested value, the direct step to it from x_k; kept if its
    // corrector converges on the same curve (test_jump), else the QP predictor takes over.
    std::optional<nlp::SolverSummary> direct;
    if (o_.predictor == Predictor::trivial_then_qp && tried_value != l) {
      tried_value = l;
      nlp::SolverSummary s = correct(target, x_k, std::nullopt, &solve_k, true);
      if (s.termination == nlp::Termination::user_stop ||
          (s.success() && !test_jump(x_k, s.x, target - p, secant, o_).jump))
        direct = std::move(s);
      else
        result_.corrector_iterations += s.iterations;  // spent, though no point keeps them
    }
    if (direct) {
      step = remaining;
      p_new = target;
    } else if (uses_qp) {
      for (;;) {  // steps 2-18 (on a stop request the corrector below refuses to evaluate: user_stop)
        ++point.predictor_attempts;
        step = std::min(trust_, remaining);  // step 2: exact hits without shrinking Delta
        p_new = step == remaining ? target : p + direction * step;
        const QpPredictorResult pr = qp_predictor(*family_.at(p_new), x_k, settings_, W1_at_k ? &*W1_at_k : nullptr);
        if (o_.reuse_predictor_hessian && pr.W1.size() > 0) W1_at_k = pr.W1;
        point.predictor_steps += pr.steps;
        const bool accepted = pr.outcome == PredictorOutcome::both_steps && pr.kappa < 1.0;
        if (accepted || step <= o_.min_trust_region) {
          x_start = pr.x;
          W = pr.W;
          point.kappa = pr.kappa;
          next_trust = accepted ? std::min(max_trust_, trust_ / o_.tau) : trust_;
          break;
        }
        const double factor = pr.outcome == PredictorOutcome::no_step ? o_.tau * o_.tau : o_.tau;
        trust_ = std::max(o_.min_trust_region, factor * trust_);
        if (o_.corrector.should_stop && o_.corrector.should_stop()) break;
      }
    } else {
      step = std::min(trivial_step > 0.0 ? trivial_step : o_.fixed_step > 0.0 ? o_.fixed_step : remaining, remaining);
      p_new = step == remaining ? target : p + direction * step;
    }
    point.trust_region = uses_qp && !direct ? trust_ : step;
    point.parameter = p_new;
    point.on_grid = on_grid(p_new);
    point.corrector = direct ? std::move(*direct) : correct(p_new, x_start, W, &solve_k, false);
    point.converged = point.corrector.success();
    point.x = point.corrector.x;
    point.objective = point.corrector.objective;
    point.seconds = seconds_since(t0);
    if (point.corrector.termination == nlp::Termination::user_stop) {
      result_.message = "stopped";
      break;
    }
    const double delta_p = p_new - p;
    if (!point.converged) {
      point.curve_id = curve_;
      if (!emit(std::move(point))) {
        result_.message = "stopped";
        break;
      }
      if (step <= o_.min_trust_region) {
        result_.message = "corrector failed at the minimal step at p = " + std::to_string(p_new);
        break;
      }
      if (uses_qp)
        trust_ = std::max(o_.min_trust_region, o_.tau * o_.tau * step);
      else
        trivial_step = std::max(o_.min_trust_region, 0.5 * step);
      continue;
    }
    const JumpTest jt = test_jump(x_k, point.x, delta_p, secant, o_);
    if (jt.jump) {
      result_.jumps.push_back({curve_, next_curve_, p, p_new, f_k, point.objective, jt.relative_distance});
      curve_ = next_curve_++;
      secant.reset();
    } else {
      secant = jt.secant;
    }
    point.curve_id = curve_;
    x_k = point.x;
    W1_at_k.reset();
    f_k = point.objective;
    solve_k = point.corrector;
    p = p_new;
    trust_ = next_trust;
    trivial_step = 0.0;
    const bool go_on = emit(std::move(point));
    if (p == grid_.back()) {
      result_.finished = true;
      result_.message = "reached the last parameter value";
      break;
    }
    if (!go_on) {
      result_.message = "stopped";
      break;
    }
    if (to_each_value && p == target) ++l;
    result_.next_curve_id = next_curve_;
    report_state();
  }
  result_.next_curve_id = next_curve_;
  result_.seconds = seconds_since(start);
  return std::move(result_);
}

}  // namespace

ContinuationResult continue_solution(const ParametricProblem& family, const VectorXd& x0, const std::vector<double>& parameters,
                                     const ContinuationOptions& options, const CurveStart& start, const PointCallback& on_point,
                                     const StateCallback& on_state) {
  validate(options);
  check_parameters(parameters);
  return Run(family, parameters, options, start, on_point, on_state).run(x0);
}

ContinuationResult resume_solution(const ParametricProblem& family, const RunState& state,
                                   const std::vector<double>& parameters, const ContinuationOptions& options,
                                   const PointCallback& on_point, const StateCallback& on_state) {
  validate(options);
  check_parameters(parameters);
  if (state.result.points.empty() || !state.result.points.back().converged || state.next_value < 1 ||
      state.next_value >= parameters.size())
    throw std::invalid_argument("resume_solution: the state does not end at a converged point before the last value");
  return Run(family, parameters, options, {state.curve_id, state.result.next_curve_id}, on_point, on_state).resume(state);
}

}  // namespace cyclopt::continuation
