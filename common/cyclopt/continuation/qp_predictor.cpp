#include "cyclopt/continuation/qp_predictor.hpp"

#include "cyclopt/continuation/lagrangian_hessian.hpp"
#include "cyclopt/nlp/sqp_building_blocks.hpp"
#include "cyclopt/qp/convex_solve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace cyclopt::continuation {

namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// Merit values are exact to rounding only; the same allowance as the SQP's (sqp_solver.cpp).
constexpr double kMeritNoiseUlps = 10.0;

// A point of the predictor with its evaluation (with derivatives) and least-squares multipliers.
struct Iterate {
  VectorXd x;
  nlp::Evaluation e;
  nlp::LeastSquaresMultipliers y;
};

struct FullStep {
  Iterate next;
  VectorXd d;                  // x_{k,j} - x_{k,j-1} (with SOC)
  std::vector<int> active;     // QP working-set inequalities
};

class Predictor {
 public:
  Predictor(nlp::Problem& problem, const QpPredictorSettings& s)
      : problem_(problem), s_(s), lower_(problem.lower_bounds()), upper_(problem.upper_bounds()) {}

  std::optional<Iterate> iterate_at(const VectorXd& x, const std::vector<int>& qp_active) {
    Iterate it{x, {}, {}};
    if (!problem_.evaluate(x, true, it.e).ok || !finite(it.e)) return std::nullopt;
    nlp::ActiveConstraints a{qp_active, {}};
    for (Index i = 0; i < it.e.inequalities.size(); ++i)
      if (it.e.inequalities[i] >= -s_.active_tolerance && std::find(a.inequalities.begin(), a.inequalities.end(), i) == a.inequalities.end())
        a.inequalities.push_back(static_cast<int>(i));
    for (Index i = 0; i < x.size(); ++i)
      if (x[i] <= lower_[i] + s_.constraint_tolerance || x[i] >= upper_[i] - s_.constraint_tolerance)
        a.bounds.push_back(static_cast<int>(i));
    it.y = nlp::least_squares_multipliers(it.e, a);  // eq. (6.26)
    return it;
  }

  // W from (6.23)/(6.24) at an iterate.
  MatrixXd clamped_hessian_at(const Iterate& it) {
    return nlp::clamped_hessian(lagrangian_hessian(problem_, it.x, it.e, it.y.equality, it.y.inequality));
  }

  // Steps 4-6 (8-10, 12-14): QP (6.7), penalties (6.9), the full step and, if the merit test
  // (6.19) fails on it, the full step with second-order correction (6.18). Nothing if either the
  // QP is incompatible, no trial point has a real solution, or neither passes (6.19).
  std::optional<FullStep> full_step(const Iterate& at, const MatrixXd& W, qp::WorkingSet& warm) {
    ++steps_;
    const nlp::LinearisationPoint lin{at.e, at.x, lower_, upper_};
    const qp::QpSolution qp = qp::solve_convex(nlp::sqp_subproblem(lin, W), s_.qp, warm, qp::ScreeningOptions{});
    if (qp.status != qp::QpStatus::optimal) return std::nullopt;
    warm = qp.working_set;
    nlp::Penalties mu{qp.equality_multipliers.cwiseAbs(), qp.inequality_multipliers};
    const double floor = s_.relative_min_penalty * mu.max();  // eq. (6.9)
    mu.equality = mu.equality.cwiseMax(floor);
    mu.inequality = mu.inequality.cwiseMax(floor);
    const VectorXd zero = VectorXd::Zero(at.x.size());
    const double q_reduction = nlp::l1_model(at.e, W, zero, mu) - nlp::l1_model(at.e, W, qp.x, mu);
    const double phi0 = nlp::l1_merit(at.e, mu);
    const double noise = kMeritNoiseUlps * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(phi0));
    const auto passes = [&](const nlp::Evaluation& e) { return phi0 - nlp::l1_merit(e, mu) >= s_.eta * q_reduction - noise; };
    const std::vector<int>& active = qp.working_set.inequalities;
    std::optional<Iterate> trial = iterate_at(project(at.x + qp.x), active);
    if (!trial) return std::nullopt;
    if (passes(trial->e)) return FullStep{*trial, trial->x - at.x, active};
    std::vector<int> soc_active = active;  // (6.17): working set plus constraints violated at the trial point
    for (Index i = 0; i < trial->e.inequalities.size(); ++i)
      if (trial->e.inequalities[i] > 0.0 && std::find(soc_active.begin(), soc_active.end(), i) == soc_active.end())
        soc_active.push_back(static_cast<int>(i));
    const VectorXd d_soc = nlp::second_order_correction(trial->e, soc_active);
    std::optional<Iterate> corrected = iterate_at(project(at.x + qp.x + d_soc), active);
    if (!corrected || !passes(corrected->e)) return std::nullopt;
    return FullStep{*corrected, corrected->x - at.x, active};
  }

  // r of (6.21) enters through damped_bfgs_update; y of (6.20) with the new point's multipliers.
  static void bfgs(MatrixXd& W, const Iterate& from, const Iterate& to) {
    const VectorXd y = nlp::lagrangian_gradient(to.e, to.y.equality, to.y.inequality, {}) -
                       nlp::lagrangian_gradient(from.e, to.y.equality, to.y.inequality, {});
    nlp::damped_bfgs_update(W, to.x - from.x, y);
  }

  int steps() const { return steps_; }

 private:
  static bool finite(const nlp::Evaluation& e) {
    return std::isfinite(e.objective) && e.equalities.allFinite() && e.inequalities.allFinite() && e.gradient.allFinite() &&
           e.equality_jacobian.allFinite() && e.inequality_jacobian.allFinite();
  }
  VectorXd project(const VectorXd& x) const { return x.cwiseMax(lower_).cwiseMin(upper_); }

  nlp::Problem& problem_;
  const QpPredictorSettings& s_;
  const VectorXd lower_, upper_;
  int steps_ = 0;
};

}  // namespace

QpPredictorResult qp_predictor(nlp::Problem& problem, const VectorXd& x_k, const QpPredictorSettings& settings,
                               const MatrixXd* given_W1) {
  Predictor pred(problem, settings);
  QpPredictorResult r;
  r.x = x_k;
  r.W = MatrixXd::Identity(x_k.size(), x_k.size());
  const std::optional<Iterate> x0 = pred.iterate_at(x_k, {});  // step 3
  if (!x0) return r;
  const MatrixXd W1 = given_W1 ? *given_W1 : pred.clamped_hessian_at(*x0);
  r.W = r.W1 = W1;
  qp::WorkingSet warm;
  const std::optional<FullStep> s1 = pred.full_step(*x0, W1, warm);  // steps 4-6
  r.steps = pred.steps();
  if (!s1) return r;  // step 18
  r.outcome = PredictorOutcome::first_step;
  r.x = s1->next.x;
  MatrixXd W2 = W1;
  std::optional<FullStep> s2;
  if (settings.fresh_second_hessian) {
    W2 = pred.clamped_hessian_at(s1->next);  // step 7
    s2 = pred.full_step(s1->next, W2, warm);  // steps 8-10
  }
  if (!s2) {  // steps 11-14: (retry) d_2 with the BFGS update (6.22) of W_1
    W2 = W1;
    Predictor::bfgs(W2, *x0, s1->next);
    s2 = pred.full_step(s1->next, W2, warm);
  }
  r.steps = pred.steps();
  r.W = W2;
  if (!s2) return r;  // step 17
  Predictor::bfgs(W2, s1->next, s2->next);  // step 15: W_3
  r.outcome = PredictorOutcome::both_steps;
  r.x = s2->next.x;
  r.W = W2;
  r.kappa = s2->d.norm() / (s1->d + s2->d).norm();  // eq. (7.2)
  return r;
}

}  // namespace cyclopt::continuation
