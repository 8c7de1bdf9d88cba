#include "cyclopt/nlp/sqp_solver.hpp"

#include "cyclopt/nlp/active_set_projections.hpp"
#include "cyclopt/nlp/cached_evaluator.hpp"
#include "cyclopt/nlp/clarke_stationarity.hpp"
#include "cyclopt/nlp/damped_bfgs.hpp"
#include "cyclopt/nlp/difference_hessian.hpp"
#include "cyclopt/nlp/kkt_measures.hpp"
#include "cyclopt/nlp/l1_merit.hpp"
#include "cyclopt/nlp/sqp_subproblems.hpp"
#include "cyclopt/nlp/wall_clock.hpp"
#include "cyclopt/qp/convex_solve.hpp"
#include "cyclopt/qp/dual_active_set_solver.hpp"
#include "cyclopt/qp/positive_part_qp.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cyclopt::nlp {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// Step 5: m_k(0) = m_k(d_LP) "within rounding" means no linearised progress is possible.
constexpr double kStationaryViolationRatio = 1e-12;
// Merit values are exact only to rounding: near a solution the predicted decrease q_red falls
// below the noise of phi_1 and every step would be rejected. The decrease tests (6.15)/(6.19)
// therefore allow this many ulps of |phi_1| of measured increase (a deviation from the seed).
constexpr double kMeritNoiseUlps = 10.0;
// Steps 6/7: rho-increases of the penalty before giving up (rho^60 ~ 1e18 for rho = 2).
constexpr int kMaxPenaltyIncreases = 60;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kShortStep = 1e-4;
constexpr int kStalledIterations = 25;
// An iterate counts as stationary for the kink model when its residual with the model band's
// kinks is below TolOpt or below this fraction of its residual with the test band's.
constexpr double kModelStationary = 1e-2;

// The multipliers at an iterate: least squares (6.26) for step 2's KKT test and the BFGS update;
// with kinks (SqpOptions::kinks) also the Clarke multipliers of the kinked terms near their kink in
// the QP's band (those of the Lagrangian whose curvature W models) and in the test's band (the
// nonsmooth KKT test).
struct IterateMultipliers {
  LeastSquaresMultipliers ls;
  ClarkeMultipliers model, test;  // empty without kinks
};

// A search direction d_k with the penalties that make the l1 merit accept it (steps 3-7).
struct SearchDirection {
  VectorXd d;
  Penalties mu;
  bool compatible = true;             // the QP (6.7) had a feasible solution
  NearKinks kinks;                    // the kinked terms the QP modelled (issue 52); none: the smooth model
  std::vector<int> active_inequalities;  // working set of the subproblem solved
  std::vector<int> held_kinks;           // samples of `kinks` the QP's step holds at their kink
};

// The samples of `kinks` whose linearised value vanishes (to rounding) at the step d.
std::vector<int> held_kinks(const KinkedTerms& terms, const NearKinks& kinks, const VectorXd& d) {
  std::vector<int> held;
  const double d_norm = d.lpNorm<Eigen::Infinity>();
  for (int s : kinks.samples) {
    const double p = terms.values[s], change = terms.jacobian.row(s).dot(d);
    if (std::abs(p + change) <= 1e-8 * (std::abs(p) + terms.jacobian.row(s).lpNorm<Eigen::Infinity>() * d_norm)) held.push_back(s);
  }
  return held;
}

class SqpRun {
 public:
  SqpRun(Problem& problem, const SolverOptions& options, SolverSummary& summary)
      : options_(options),
        sqp_(options.sqp),
        summary_(summary),
        evaluator_(problem, summary, options.should_stop),
        n_(problem.num_variables()),
        m_eq_(problem.num_equalities()),
        m_in_(problem.num_inequalities()),
        lower_(problem.lower_bounds()),
        upper_(problem.upper_bounds()),
        start_(Clock::now()),
        trust_radius_(sqp_.initial_trust_radius),
        min_trust_radius_(sqp_.min_trust_radius),
        max_trust_radius_(sqp_.max_trust_radius),
        scalar_penalty_(sqp_.initial_penalty),
        model_band_(sqp_.kinks.model_band) {}

  void run(const VectorXd& x0);

 private:
  double elapsed() const { return seconds_since(start_); }
  VectorXd project(const VectorXd& x) const { return x.cwiseMax(lower_).cwiseMin(upper_); }
  LinearisationPoint here() const { return {current_, x_, lower_, upper_}; }
  // The kinked terms are modelled (SqpOptions::kinks) and the problem declares some.
  bool kinks_on() const { return sqp_.kinks.enabled && !current_.kinks.empty(); }
  const NearKinks& model_kinks() const { return multipliers_.model.kinks; }
  IterateMultipliers multipliers_at(const Evaluation& e, const VectorXd& x, const ActiveConstraints& active) const;
  // The model band shrinks at a point stationary for it but not for the test band (below).
  void shrink_model_band(const ActiveConstraints& active);
  // The QP (6.7), boxed by the evaluable step bound, with the kinked terms `kinks` as positive parts
  // if kinked (sqp_subproblems.hpp).
  qp::QpSolution solve_subproblem(bool kinked, const NearKinks& kinks);
  void stop(Termination t, std::string message) {
    const bool stopped = evaluator_.stopped();  // the failure that ended the run was a refused evaluation
    summary_.termination = stopped ? Termination::user_stop : t;
    summary_.message = stopped ? "stopped by should_stop (" + message + ")" : std::move(message);
  }
  bool is_kkt_point();
  std::optional<SearchDirection> search_direction();
  std::optional<SearchDirection> relaxed_direction();
  bool evaluates(const VectorXd& x) { return evaluator_.evaluate(project(x), false).ok; }
  std::optional<VectorXd> line_search(const SearchDirection& dir);
  MatrixXd restarted_hessian(const VectorXd& step, const VectorXd& gradient_change);
  // The forward-difference Hessian of the Lagrangian (6.23) at x_k, if it evaluates.
  std::optional<MatrixXd> difference_hessian() {
    if (!kinks_on()) return lagrangian_hessian_by_differences(evaluator_, x_, current_, multipliers_.ls.equality, multipliers_.ls.inequality);
    const ClarkeMultipliers& y = multipliers_.model;
    return lagrangian_hessian_by_differences(evaluator_, x_, current_, y.equality, y.inequality, 1.0, y.kinks, y.kink);
  }
  ActiveConstraints active_at(const VectorXd& x, const std::vector<int>& inequalities) const;
  // SqpOptions::progress_window: records `latest` and ends the run (stalled) without progress.
  bool stalled_over_window(const IterationReport& latest);
  void finish();

  const SolverOptions& options_;
  const SqpOptions& sqp_;
  SolverSummary& summary_;
  CachedEvaluator evaluator_;
  const Index n_, m_eq_, m_in_;
  const VectorXd lower_, upper_;
  const Clock::time_point start_;

  VectorXd x_;
  Evaluation current_;  // at x_, with derivatives
  IterateMultipliers multipliers_;
  MatrixXd W_;
  qp::WorkingSet working_set_;  // of the last compatible QP (6.7): warm start of the next
  VectorXd kink_sigma_;         // per sample, the last kinked QP's sigma (NaN where it did not model the sample)
  double trust_radius_, min_trust_radius_, max_trust_radius_;
  double scalar_penalty_;  // max of the previous penalties, eq. (6.10)
  double model_band_;      // SqpOptions::kinks.model_band, shrunk by shrink_model_band
  double q_reduction_ = 0.0;
  double step_bound_ = kInfinity;  // box on d in (6.7), see line_search
  int short_steps_ = 0;  // consecutive accepted steps below kShortStep
  std::vector<IterationReport> history_;  // of iterations 1, 2, ... (only with sqp_.progress_window > 0)
  double smallest_kkt_before_window_ = kInfinity;  // over history_ before its last progress_window entries
};

ActiveConstraints SqpRun::active_at(const VectorXd& x, const std::vector<int>& inequalities) const {
  ActiveConstraints a{inequalities, {}};
  for (Index i = 0; i < n_; ++i)
    if (x[i] <= lower_[i] + options_.constraint_tolerance || x[i] >= upper_[i] - options_.constraint_tolerance)
      a.bounds.push_back(static_cast<int>(i));
  return a;
}

IterateMultipliers SqpRun::multipliers_at(const Evaluation& e, const VectorXd& x, const ActiveConstraints& active) const {
  IterateMultipliers y{least_squares_multipliers(e, active), {}, {}};
  if (!sqp_.kinks.enabled || e.kinks.empty()) return y;
  const double tol = options_.constraint_tolerance;
  y.model = clarke_multipliers(e, active, near_kinks(e.kinks, kink_band(x, model_band_)), x, lower_, upper_, tol);
  ActiveConstraints tested{{}, active.bounds};  // complementarity: the working set's rows still active
  for (int i : active.inequalities)
    if (e.inequalities[i] >= -sqp_.kinks.active_tolerance) tested.inequalities.push_back(i);
  for (Index i = 0; i < m_in_; ++i)
    if (e.inequalities[i] >= -sqp_.kinks.active_tolerance &&
        std::find(active.inequalities.begin(), active.inequalities.end(), i) == active.inequalities.end())
      tested.inequalities.push_back(static_cast<int>(i));
  y.test = clarke_multipliers(e, tested, near_kinks(e.kinks, kink_band(x, sqp_.kinks.test_band)), x, lower_, upper_, tol);
  return y;
}

// The kinked terms the QP models are those within the model band; a sample there whose power only
// passes slowly through zero (not held) looks like a kink to the QP, and an iterate can become
// stationary for that model (kModelStationary) without being a Clarke point of f (not in the seed;
// the reduction of the radius of Goldstein-type epsilon-subdifferential methods): then the band
// shrinks tenfold, down to the test band, and the samples outside it keep their smooth branch again.
void SqpRun::shrink_model_band(const ActiveConstraints& active) {
  const double tol = options_.optimality_tolerance;
  while (kinks_on() && model_band_ > sqp_.kinks.test_band && multipliers_.test.residual > tol &&
         multipliers_.model.residual <= std::max(tol, kModelStationary * multipliers_.test.residual)) {
    model_band_ = std::max(sqp_.kinks.test_band, 0.1 * model_band_);
    multipliers_.model = clarke_multipliers(current_, active, near_kinks(current_.kinks, kink_band(x_, model_band_)), x_,
                                            lower_, upper_, options_.constraint_tolerance);
    if (options_.print_level > 1) std::printf("sqp        kink model band %.1e\n", model_band_);
  }
}

// Step 2: |c_g| <= TolCon, max(0, c_u) <= TolCon, |grad L|_inf <= TolOpt; and multipliers of the
// right sign (a negative inequality multiplier means the active set is not yet optimal).
// With kinks, a point that fails this test passes the nonsmooth one when its Clarke residual with
// the kinked terms of the test band is below TolOpt (clarke_stationarity.hpp).
bool SqpRun::is_kkt_point() {
  const LeastSquaresMultipliers& y = multipliers_.ls;
  summary_.constraint_violation = constraint_violation(current_, x_, lower_, upper_);
  summary_.kkt_error = lagrangian_gradient(current_, y.equality, y.inequality, y.bound).lpNorm<Eigen::Infinity>();
  const double tol = options_.optimality_tolerance;
  bool signs = m_in_ == 0 || y.inequality.minCoeff() >= -tol;
  for (Index i = 0; i < n_ && signs; ++i) {
    const double nu = y.bound[i];
    const bool at_lower = x_[i] <= lower_[i] + options_.constraint_tolerance;
    const bool at_upper = x_[i] >= upper_[i] - options_.constraint_tolerance;
    if ((nu < -tol && !at_lower) || (nu > tol && !at_upper)) signs = false;
  }
  const bool feasible = summary_.constraint_violation <= options_.constraint_tolerance;
  summary_.optimality = Optimality::none;
  if (feasible && summary_.kkt_error <= tol && signs) {
    summary_.optimality = Optimality::kkt;
    return true;
  }
  if (!kinks_on()) return false;
  const ClarkeMultipliers& clarke = multipliers_.test;
  summary_.kkt_error = std::min(summary_.kkt_error, clarke.residual);
  if (!feasible || clarke.residual > tol) return false;
  summary_.optimality = clarke.kinks.empty() ? Optimality::kkt : Optimality::nonsmooth_kkt;
  return true;
}

qp::QpSolution SqpRun::solve_subproblem(bool kinked, const NearKinks& kinks) {
  const KinkedSubproblem sub = kinked ? kinked_sqp_subproblem(here(), W_, kinks) : KinkedSubproblem{sqp_subproblem(here(), W_), {}};
  // The dual of the kinked QP starts where the last one ended: its working set, and per sample its
  // sigma or, for a sample it did not model, the branch the gradient took (w_s where p_s > 0).
  qp::PositivePartQpStart start{working_set_, VectorXd(kinks.size())};
  if (kink_sigma_.size() != current_.kinks.values.size())
    kink_sigma_ = VectorXd::Constant(current_.kinks.values.size(), std::numeric_limits<double>::quiet_NaN());
  for (Index k = 0; k < kinks.size(); ++k) {
    const int s = kinks.samples[static_cast<size_t>(k)];
    start.sigma[k] = std::isnan(kink_sigma_[s]) ? (current_.kinks.values[s] > 0.0 ? kinks.weights[k] : 0.0) : kink_sigma_[s];
  }
  const auto solve = [&](const qp::QuadraticProgram& p) {
    if (!kinked) return qp::solve_convex(p, sqp_.qp, working_set_, sqp_.screening);
    const qp::PositivePartQpSolution solution = qp::solve_positive_part_qp(p, sub.terms, sqp_.qp, start);
    kink_sigma_.setConstant(std::numeric_limits<double>::quiet_NaN());
    kink_sigma_(kinks.samples) = solution.sigma;
    return solution.qp;
  };
  qp::QpSolution qp;
  if (std::isfinite(step_bound_)) {
    qp::QuadraticProgram boxed = sub.qp;
    boxed.lower_bounds = boxed.lower_bounds.cwiseMax(-step_bound_);
    boxed.upper_bounds = boxed.upper_bounds.cwiseMin(step_bound_);
    qp = solve(boxed);
    summary_.qp_iterations += qp.iterations;
    if (qp.status == qp::QpStatus::infeasible) step_bound_ = kInfinity;  // the box, not (6.7), may be incompatible
  }
  if (!std::isfinite(step_bound_)) {
    qp = solve(sub.qp);
    summary_.qp_iterations += qp.iterations;
  }
  return qp;
}

// Step 3: the QP (6.7) and the penalties (6.9); with kinks (issue 52) the kinked terms near their
// kink enter as positive parts. (They are not added lazily where the QP's step crosses a kink, as
// the l1 relaxation adds slacks: from distant starts the first steps cross most of f_mech's 1200
// kinks, and modelling those made each QP two orders of magnitude costlier - measured.)
std::optional<SearchDirection> SqpRun::search_direction() {
  const bool kinked = kinks_on() && !model_kinks().empty() && qp::is_strictly_convex(W_, sqp_.qp.curvature_tolerance);
  NearKinks kinks = kinked ? model_kinks() : NearKinks{};
  qp::QpSolution qp = solve_subproblem(kinked, kinks);
  if (kinked && qp.status == qp::QpStatus::max_iterations) {  // the seed's QP then: the kinks' model is an addition
    if (options_.print_level > 0) std::printf("sqp        kinked QP unfinished after %d iterations: QP (6.7) instead\n", qp.iterations);
    kinks = {};
    qp = solve_subproblem(false, kinks);
  }
  if (qp.status == qp::QpStatus::infeasible) return relaxed_direction();
  if (qp.status != qp::QpStatus::optimal) {
    stop(Termination::numerical_failure, std::string("QP subproblem (6.7): ") + qp::to_string(qp.status) + ": " + qp.message);
    return std::nullopt;
  }
  working_set_ = qp.working_set;
  if (options_.print_level > 1)
    std::printf("sqp        QP (6.7): %d iterations (%d in phase 1), %zu active, %lld kinked samples modelled\n", qp.iterations,
                qp.phase_one_iterations,
                qp.working_set.inequalities.size() + qp.working_set.lower_bounds.size() + qp.working_set.upper_bounds.size(),
                static_cast<long long>(kinks.size()));
  SearchDirection dir{qp.x, {qp.equality_multipliers.cwiseAbs(), qp.inequality_multipliers}, true, std::move(kinks),
                      qp.working_set.inequalities, {}};
  dir.held_kinks = held_kinks(current_.kinks, dir.kinks, dir.d);
  const double floor = sqp_.relative_min_penalty * dir.mu.max();  // eq. (6.9a/b)
  dir.mu.equality = dir.mu.equality.cwiseMax(floor);
  dir.mu.inequality = dir.mu.inequality.cwiseMax(floor);
  return dir;
}

// Steps 4-7: the QP is incompatible. l1 relaxation (6.13) with scalar penalty (6.10), raised by
// rho until the step achieves a fraction of the LP's (6.14) decrease of linearised violation.
std::optional<SearchDirection> SqpRun::relaxed_direction() {
  // eq. (6.10): mu_k = max of the previous penalties (mu_1 initially). A previous maximum of 0
  // (no active constraint so far) would make the rho-increase futile; mu_1 is used then.
  double mu = sqp_.penalty_increase * (scalar_penalty_ > 0.0 ? scalar_penalty_ : sqp_.initial_penalty);
  const qp::QpSolution lp = solve_l1_feasibility_lp(here(), trust_radius_, sqp_.qp, sqp_.screening);
  summary_.qp_iterations += lp.iterations;
  // The LP only calibrates the penalty (steps 6/7) and certifies infeasibility (step 5). If it
  // hits the QP iteration limit (degenerate LPs with many slacks), its last point still bounds the
  // achievable decrease from below: use that and skip the certificate (a deviation from the seed).
  const bool lp_solved = lp.status == qp::QpStatus::optimal;
  if (!lp_solved && lp.status != qp::QpStatus::max_iterations) {
    stop(Termination::numerical_failure, std::string("LP (6.14): ") + qp::to_string(lp.status) + ": " + lp.message);
    return std::nullopt;
  }
  if (!lp_solved && options_.print_level > 0) std::printf("sqp        LP (6.14) unfinished after %d iterations\n", lp.iterations);
  const VectorXd zero = VectorXd::Zero(n_);
  const double m0 = linearized_violation(current_, zero);
  const double lp_decrease = std::max(0.0, m0 - linearized_violation(current_, lp.x.head(n_)));
  if (lp_solved && m0 > 0.0 && lp_decrease <= kStationaryViolationRatio * m0) {  // step 5
    stop(Termination::infeasible, "infeasible stationary point of the constraint violation (Algorithm 1, step 5)");
    return std::nullopt;
  }
  qp::WorkingSet warm;
  for (int k = 0;; ++k) {
    const qp::QpSolution relaxed = solve_l1_relaxed_subproblem(here(), W_, mu, sqp_.qp, sqp_.screening, warm);
    summary_.qp_iterations += relaxed.iterations;
    if (relaxed.status != qp::QpStatus::optimal) {
      stop(Termination::numerical_failure, std::string("relaxed QP (6.13): ") + qp::to_string(relaxed.status) + ": " + relaxed.message);
      return std::nullopt;
    }
    warm = relaxed.working_set;
    if (options_.print_level > 1)
      std::printf("sqp        relaxed QP (6.13), mu = %.3e: %d iterations, %lld variables; LP (6.14): %d iterations\n", mu,
                  relaxed.iterations, static_cast<long long>(relaxed.x.size()), lp.iterations);
    SearchDirection dir{relaxed.x.head(n_), Penalties::uniform(mu, m_eq_, m_in_), false, {}, relaxed.working_set.inequalities, {}};
    const bool enough_violation_decrease = m0 - linearized_violation(current_, dir.d) >= sqp_.epsilon1 * lp_decrease;  // step 6
    const bool enough_model_decrease = l1_model(current_, W_, zero, dir.mu) - l1_model(current_, W_, dir.d, dir.mu) >=
                                       sqp_.epsilon2 * mu * lp_decrease;  // step 7
    if ((enough_violation_decrease && enough_model_decrease) || k == kMaxPenaltyIncreases) return dir;
    mu *= sqp_.penalty_increase;
  }
}

// Steps 8-13. Returns x_{k+1}, or nothing (termination set) if no acceptable point is found.
std::optional<VectorXd> SqpRun::line_search(const SearchDirection& dir) {
  const VectorXd zero = VectorXd::Zero(n_);
  q_reduction_ = l1_model(current_, W_, zero, dir.mu, dir.kinks) - l1_model(current_, W_, dir.d, dir.mu, dir.kinks);  // step 8
  const double phi0 = l1_merit(current_, dir.mu);
  const double noise = kMeritNoiseUlps * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(phi0));
  const double tau = sqp_.backtracking, eta = sqp_.armijo;
  // Step 9: shorten until the point has a (real) solution.
  double beta = 1.0;
  VectorXd d = dir.d;
  for (int k = 0; !evaluates(x_ + d); ++k) {
    if (k == sqp_.max_backtracking_steps) {
      stop(Termination::evaluation_failure, "no evaluable point along the search direction (Algorithm 1, step 9)");
      return std::nullopt;
    }
    beta *= tau;
    d = beta * dir.d;
  }
  // Evaluable step bound (a deviation from the seed): the next QP (6.7) steps stay within the
  // length that had a real solution here, and the bound doubles after each full step. Without it
  // iterates at the edge of the domain of real solutions take QP steps thousands of times too long
  // and spend all of MaxFun on step 9 (seen on the walker: beta ~ 5e-4 for hundreds of iterations).
  if (sqp_.evaluable_step_bound && dir.compatible)
    step_bound_ = beta < 1.0 ? beta * dir.d.lpNorm<Eigen::Infinity>() : 2.0 * step_bound_;
  // Step 10: merit test (6.15).
  if (phi0 - l1_merit(evaluator_.evaluation(), dir.mu) >= eta * beta * q_reduction_ - noise) return project(x_ + d);
  // Step 11: EQP projection (6.16)-(6.18) at x_k + d_k, only if the QP (6.7) was compatible; with
  // kinks also onto the kinks the QP held (issue 52): their second-order error would otherwise cost
  // positive work the model did not predict, the Maratos effect of a kink.
  VectorXd d_soc = zero;
  if (dir.compatible && sqp_.second_order_correction && evaluator_.evaluate(project(x_ + d), true).ok) {
    const Evaluation& trial = evaluator_.evaluation();
    std::vector<int> active = dir.active_inequalities;
    for (Index i = 0; i < m_in_; ++i)
      if (trial.inequalities[i] > 0.0 && std::find(active.begin(), active.end(), i) == active.end())
        active.push_back(static_cast<int>(i));
    d_soc = second_order_correction(trial, active, dir.held_kinks);
    if (!evaluates(x_ + d + d_soc)) d_soc = zero;
  }
  // Step 12: backtracking on (6.19); failing evaluations count as "not acceptable".
  double alpha = 1.0;
  for (int k = 0; k <= sqp_.max_backtracking_steps; ++k, alpha *= tau) {
    const VectorXd trial = project(x_ + alpha * d + alpha * alpha * d_soc);
    if (evaluates(trial) && phi0 - l1_merit(evaluator_.evaluation(), dir.mu) >= eta * alpha * beta * q_reduction_ - noise) {
      if (options_.print_level > 1)
        std::printf("sqp        line search: beta %.1e (real solution), alpha %.1e (6.19)%s, model reduction %.3e\n", beta, alpha,
                    d_soc.isZero() ? "" : " with second-order correction", q_reduction_);
      return trial;  // step 13
    }
  }
  stop(Termination::numerical_failure, "line search found no sufficient decrease of the l1 merit (Algorithm 1, step 12)");
  return std::nullopt;
}

void SqpRun::run(const VectorXd& x0) {
  x_ = project(x0);
  if (!evaluator_.evaluate(x_, true).ok) {  // step 1
    stop(Termination::evaluation_failure, "evaluation failed at the start point: " + evaluator_.evaluate(x_, true).reason);
    summary_.x = x_;
    return;
  }
  current_ = evaluator_.evaluation();
  std::vector<int> initially_active;
  for (Index i = 0; i < m_in_; ++i)
    if (current_.inequalities[i] >= -options_.constraint_tolerance) initially_active.push_back(static_cast<int>(i));
  multipliers_ = multipliers_at(current_, x_, active_at(x_, initially_active));
  shrink_model_band(active_at(x_, initially_active));
  bool identity_start = true;

  for (int k = 1;; ++k) {
    if (is_kkt_point()) {  // step 2
      stop(Termination::converged, "KKT point (Algorithm 1, step 2)");
      break;
    }
    // Step 18 (checked before the work of iteration k).
    if (k > options_.max_iterations) {
      stop(Termination::max_iterations, "MaxIter reached");
      break;
    }
    if (elapsed() > options_.max_wall_seconds) {
      stop(Termination::time_limit, "MaxTime reached");
      break;
    }
    if (options_.should_stop && options_.should_stop()) {
      stop(Termination::user_stop, "stopped by should_stop");
      break;
    }
    if (summary_.function_evaluations + summary_.jacobian_evaluations > sqp_.max_function_evaluations) {
      stop(Termination::max_iterations, "MaxFun reached");
      break;
    }
    if (sqp_.max_qp_iterations > 0 && summary_.qp_iterations > sqp_.max_qp_iterations) {
      stop(Termination::max_iterations, "MaxQpIter reached: " + std::to_string(summary_.qp_iterations) +
                                            " active-set iterations in the QP subproblems");
      break;
    }
    if (current_.objective < sqp_.objective_limit) {
      stop(Termination::numerical_failure, "objective below ObjLimit: probably unbounded below");
      break;
    }
    if (k == 1) {  // W_1 after the test of step 2: a start at a KKT point (a continuation's first point) needs none
      std::optional<MatrixXd> hessian;  // of the Lagrangian (6.23)
      if (sqp_.lagrangian_hessian)
        hessian = sqp_.lagrangian_hessian(x_, multipliers_.ls.equality, multipliers_.ls.inequality);
      else if (sqp_.difference_hessian)
        hessian = difference_hessian();
      identity_start = !hessian;
      W_ = identity_start ? MatrixXd::Identity(n_, n_) : clamped_hessian(*hessian);  // (6.24)
    }
    const std::optional<SearchDirection> dir = search_direction();  // steps 3-7
    if (!dir) break;
    if (dir->compatible && dir->d.lpNorm<Eigen::Infinity>() <= sqp_.step_tolerance) {  // step 3
      const bool feasible = summary_.constraint_violation <= options_.constraint_tolerance;
      stop(feasible ? Termination::acceptable : Termination::numerical_failure,
           "step below TolStep: potential KKT point (Algorithm 1, step 3)");
      break;
    }
    const std::optional<VectorXd> next = line_search(*dir);  // steps 8-13
    if (!next) break;
    const VectorXd step = *next - x_;
    const double step_norm = step.lpNorm<Eigen::Infinity>();
    const double actual_reduction = l1_merit(current_, dir->mu) - l1_merit(evaluator_.evaluation(), dir->mu);
    if (k == 2) {  // step 14: trust-region limits relative to the size of the second step
      min_trust_radius_ *= step_norm;
      max_trust_radius_ *= step_norm;
    }
    // Step 15. The OCR reads |x_k|_2 here; the trust region of [48] follows the step length, so
    // |d_k|_inf (the norm of (6.14d)) is used.
    const double factor = actual_reduction < 0.25 * q_reduction_ ? 0.5 : actual_reduction > 0.75 * q_reduction_ ? 2.0 : 1.0;
    trust_radius_ = std::min(max_trust_radius_, std::max(min_trust_radius_, factor * step_norm));
    // Step 16: derivatives and least-squares multipliers (6.26) at x_{k+1}.
    if (!evaluator_.evaluate(*next, true).ok) {
      stop(Termination::evaluation_failure, "derivatives failed at an accepted point: " + evaluator_.evaluate(*next, true).reason);
      break;
    }
    const Evaluation& e = evaluator_.evaluation();
    IterateMultipliers y = multipliers_at(e, *next, active_at(*next, dir->active_inequalities));
    // Step 17: y_k of (6.20) with the new multipliers at both points (bound terms cancel); with
    // kinks the Lagrangian of the kinked terms' multipliers, whose gradient does not jump at a kink.
    const ClarkeMultipliers& yk = y.model;
    const VectorXd gradient_change =
        sqp_.kinks.enabled && !e.kinks.empty()
            ? VectorXd(lagrangian_gradient(e, yk.equality, yk.inequality, {}, yk.kinks, yk.kink) -
                       lagrangian_gradient(current_, yk.equality, yk.inequality, {}, yk.kinks, yk.kink))
            : VectorXd(lagrangian_gradient(e, y.ls.equality, y.ls.inequality, {}) -
                       lagrangian_gradient(current_, y.ls.equality, y.ls.inequality, {}));
    short_steps_ = step_norm < kShortStep * std::max(1.0, x_.lpNorm<Eigen::Infinity>()) ? short_steps_ + 1 : 0;
    const bool stalled = short_steps_ == kStalledIterations;
    if (k == 1 && identity_start)
      W_ = scaled_identity_update(step, gradient_change);  // (6.25)
    else if (!stalled)
      damped_bfgs_update(W_, step, gradient_change);  // (6.22)
    scalar_penalty_ = dir->mu.max();
    x_ = *next;
    current_ = e;
    multipliers_ = std::move(y);
    shrink_model_band(active_at(x_, dir->active_inequalities));
    if (stalled) W_ = restarted_hessian(step, gradient_change);
    else if (sqp_.difference_hessian && sqp_.difference_hessian_every > 0 && k % sqp_.difference_hessian_every == 0)
      if (const auto H = difference_hessian()) W_ = clamped_hessian(*H);  // (6.24)
    summary_.iterations = k;
    const LeastSquaresMultipliers& ls = multipliers_.ls;
    double kkt_error = lagrangian_gradient(current_, ls.equality, ls.inequality, ls.bound).lpNorm<Eigen::Infinity>();
    if (kinks_on()) kkt_error = std::min(kkt_error, multipliers_.test.residual);
    IterationReport report{k, current_.objective, constraint_violation(current_, x_, lower_, upper_), kkt_error, step_norm,
                           elapsed()};
    if (options_.print_level > 0)
      std::printf("sqp %4d  f %+.10e  viol %.3e  kkt %.3e  step %.3e  %s%s\n", k, report.objective, report.constraint_violation,
                  report.kkt_error, report.step_norm, dir->compatible ? "" : "(l1-relaxed)",
                  model_kinks().empty() ? "" : (" kinks " + std::to_string(model_kinks().size())).c_str());
    if (options_.on_iteration && !options_.on_iteration(report)) {
      is_kkt_point();
      stop(Termination::user_stop, "stopped by on_iteration");
      break;
    }
    if (stalled_over_window(report)) break;
  }
  finish();
}

// A stalled BFGS matrix - kStalledIterations consecutive steps below kShortStep, as the damped
// update (6.22) builds curvature across the kinks of f_mech - is replaced by W_1's choice at the
// current point x_k: (6.24) on the difference Hessian or the scaled identity (6.25) of the last
// step. Not in the seed.
MatrixXd SqpRun::restarted_hessian(const VectorXd& step, const VectorXd& gradient_change) {
  short_steps_ = 0;
  if (options_.print_level > 0) std::printf("sqp        W restart after %d short steps\n", kStalledIterations);
  if (sqp_.difference_hessian)
    if (const auto H = difference_hessian()) return clamped_hessian(*H);
  return scaled_identity_update(step, gradient_change);
}

bool SqpRun::stalled_over_window(const IterationReport& latest) {
  const int window = sqp_.progress_window;
  if (window == 0) return false;
  history_.push_back(latest);
  if (static_cast<int>(history_.size()) <= window) return false;
  const auto window_begin = history_.end() - window;
  const IterationReport& before = *(window_begin - 1);
  const auto kkt_less = [](const IterationReport& a, const IterationReport& b) { return a.kkt_error < b.kkt_error; };
  const double kkt_in_window = std::min_element(window_begin, history_.end(), kkt_less)->kkt_error;
  // Called every iteration, so `before` is the one entry that has just left the window.
  smallest_kkt_before_window_ = std::min(smallest_kkt_before_window_, before.kkt_error);
  const double kkt_before = smallest_kkt_before_window_;
  const double decrease = before.objective - latest.objective;
  if (decrease >= sqp_.progress_min_decrease * std::max(std::abs(latest.objective), 1e-8) ||
      latest.constraint_violation < 0.5 * before.constraint_violation || kkt_in_window < 0.5 * kkt_before)
    return false;
  if (is_kkt_point()) return false;  // step 2 of the next iteration ends the run as converged
  char message[200];
  std::snprintf(message, sizeof message,
                "no progress over %d iterations: f %.6g -> %.6g, violation %.1e -> %.1e, smallest KKT error %.1e -> %.1e",
                window, before.objective, latest.objective, before.constraint_violation, latest.constraint_violation, kkt_before,
                kkt_in_window);
  stop(Termination::stalled, message);
  return true;
}

void SqpRun::finish() {
  summary_.x = x_;
  summary_.objective = current_.objective;
  if (summary_.termination != Termination::converged) summary_.optimality = Optimality::none;
  if (summary_.optimality == Optimality::nonsmooth_kkt) {
    const ClarkeMultipliers& y = multipliers_.test;
    summary_.equality_multipliers = y.equality;
    summary_.inequality_multipliers = y.inequality;
    summary_.bound_multipliers = y.bound;
    summary_.kink_multipliers = VectorXd::Zero(current_.kinks.values.size());
    summary_.kink_multipliers(y.kinks.samples) = y.kink;
  } else {
    summary_.equality_multipliers = multipliers_.ls.equality;
    summary_.inequality_multipliers = multipliers_.ls.inequality;
    summary_.bound_multipliers = multipliers_.ls.bound;
  }
  summary_.wall_seconds = elapsed();
}

}  // namespace

SolverSummary solve_with_sqp(Problem& problem, const SolverOptions& options, const VectorXd& x0) {
  validate(options);
  if (x0.size() != problem.num_variables())
    throw std::invalid_argument("x0: size must equal num_variables() = " + std::to_string(problem.num_variables()) +
                                ", got " + std::to_string(x0.size()));
  SolverSummary summary;
  SqpRun(problem, options, summary).run(x0);
  return summary;
}

}  // namespace cyclopt::nlp
