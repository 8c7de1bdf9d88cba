#include "cyclopt/studies/kkt_sensitivity.hpp"

#include "cyclopt/continuation/lagrangian_hessian.hpp"
#include "cyclopt/nlp/kkt_measures.hpp"
#include "cyclopt/walker/model_parameters.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace cyclopt::studies {

namespace {

// A row of the linearised KKT system's active set: an inequality or a bound of z.
struct ActiveRow {
  bool bound = false;
  int index = 0;        // inequality row or variable
  double sign = 1.0;    // multiplier * sign >= 0 while the row stays active (-1: a lower bound)
  double multiplier = 0.0;
};

// A candidate for the first active-set change along one direction: an inactive row with its value
// c <= 0 and rate dc/dp, or an active row with its signed multiplier and rate.
void consider(double level, double rate, double direction, const std::string& name, bool enters, ActiveSetChange& side) {
  // enters: c + t * direction * rate reaches 0 (c <= 0); leaves: m + t * direction * rate reaches 0 (m >= 0).
  const double toward = enters ? direction * rate : -direction * rate;
  if (!(toward > 0.0)) return;
  const double t = std::max(0.0, enters ? -level : level) / toward;
  if (t < side.relative_change) side = {t, name, enters};
}

}  // namespace

std::vector<std::string> sensitivity_parameters(const walker::WalkerModel<double>& model,
                                                const walker::GaitProblemOptions& problem) {
  std::vector<std::string> out;
  const std::vector<std::string> names = walker::model_parameter_names(model);
  for (int i = 0; i < static_cast<int>(names.size()); ++i)
    if (!walker::follows_foot_geometry(model, i) &&
        std::find(problem.free_parameters.begin(), problem.free_parameters.end(), names[i]) == problem.free_parameters.end())
      out.push_back(names[i]);
  return out;
}

KktSensitivity kkt_sensitivity(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                               const Eigen::VectorXd& z, const nlp::SolverSummary& s, const KktSensitivityOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<std::string> targets = o.parameters.empty() ? sensitivity_parameters(model, problem) : o.parameters;
  const std::vector<std::string> allowed = sensitivity_parameters(model, problem);
  for (const std::string& name : targets) {
    walker::model_parameter_index(model, name);  // throws with the valid names
    if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
      throw std::invalid_argument("parameters: \"" + name +
                                  "\" is optimised (free_parameters) or follows the foot geometry, not a parameter of the optimum");
  }
  walker::GaitProblem original(model, problem);
  const int n = original.num_variables(), m = original.num_inequalities(), np = static_cast<int>(targets.size());
  if (z.size() != n || s.equality_multipliers.size() != 1 || s.inequality_multipliers.size() != m ||
      (s.bound_multipliers.size() != 0 && s.bound_multipliers.size() != n))
    throw std::invalid_argument("kkt_sensitivity: z or multipliers do not match the problem's sizes");

  // The same problem with p appended to z: its first m rows are the original's (rows of free foot
  // parameters, convexity and design bounds, come after the gait's), its last np columns are d/dp.
  walker::GaitProblemOptions extended_options = problem;
  for (const std::string& name : targets) extended_options.free_parameters.push_back(name);
  walker::GaitProblem extended(model, extended_options);
  Eigen::VectorXd ze(n + np);
  ze.head(n) = z;
  const Eigen::VectorXd p_mod = walker::model_parameters(model);
  for (int k = 0; k < np; ++k) ze(n + k) = p_mod(walker::model_parameter_index(model, targets[k]));
  nlp::Evaluation e;
  const nlp::EvaluationStatus status = extended.evaluate(ze, true, e);
  if (!status.ok) throw std::invalid_argument("kkt_sensitivity: the point cannot be evaluated: " + status.reason);

  const Eigen::VectorXd& y = s.equality_multipliers;
  Eigen::VectorXd mu = Eigen::VectorXd::Zero(e.inequalities.size());
  mu.head(m) = s.inequality_multipliers;
  const Eigen::VectorXd nu = s.bound_multipliers.size() == n ? s.bound_multipliers : Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd grad_l = nlp::lagrangian_gradient(e, y, mu, {});  // dL/d[z; p], bound terms apart

  KktSensitivity out;
  out.objective = e.objective;
  out.lagrangian_gradient = (grad_l.head(n) + nu).lpNorm<Eigen::Infinity>();

  // Active set: c_g, strongly active inequalities and bounds of z; weakly active rows are left out
  // of the linearised system and checked for the side on which they would be violated.
  const Eigen::VectorXd lower = original.lower_bounds(), upper = original.upper_bounds();
  std::vector<ActiveRow> active;
  std::vector<ActiveRow> weak;
  for (int i = 0; i < m; ++i) {
    if (e.inequalities(i) < -o.active_tolerance) continue;
    (std::abs(mu(i)) > o.weak_multiplier ? active : weak).push_back({false, i, 1.0, mu(i)});
  }
  for (int j = 0; j < n; ++j) {
    const bool at_upper = upper(j) - z(j) <= o.active_tolerance, at_lower = z(j) - lower(j) <= o.active_tolerance;
    if (!at_upper && !at_lower) continue;
    (std::abs(nu(j)) > o.weak_multiplier ? active : weak).push_back({true, j, at_upper ? 1.0 : -1.0, nu(j)});
  }
  const auto row_name = [&](const ActiveRow& r) {
    return r.bound ? std::string(r.sign > 0 ? "upper" : "lower") + " bound of " + original.variable_name(r.index)
                   : original.constraint_name(false, r.index);
  };
  for (const ActiveRow& r : weak) out.weakly_active.push_back(row_name(r));
  const int na = 1 + static_cast<int>(active.size());
  out.active_constraints = na;
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(na, n + np);  // gradients of the active rows in [z; p]
  G.row(0) = e.equality_jacobian.row(0);
  for (int a = 1; a < na; ++a) {
    const ActiveRow& r = active[a - 1];
    if (r.bound)
      G(a, r.index) = 1.0;
    else
      G.row(a) = e.inequality_jacobian.row(r.index);
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> rank_check(G.leftCols(n).transpose());
  out.unique_multipliers = na <= n && rank_check.rank() == na;

  // Linearised KKT system on the active set, all parameters at once:
  //   [W  G_z'] [dz/dp    ]     [W_zp]
  //   [G_z  0 ] [dlambda/dp] = -[G_p ]
  const Eigen::MatrixXd H = continuation::lagrangian_hessian(extended, ze, e, y, mu);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + na, n + na);
  K.topLeftCorner(n, n) = H.topLeftCorner(n, n);
  K.topRightCorner(n, na) = G.leftCols(n).transpose();
  K.bottomLeftCorner(na, n) = G.leftCols(n);
  Eigen::MatrixXd rhs(n + na, np);
  rhs.topRows(n) = -H.topRightCorner(n, np);
  rhs.bottomRows(na) = -G.rightCols(np);
  const Eigen::MatrixXd d = K.completeOrthogonalDecomposition().solve(rhs);

  std::vector<bool> is_active(m, false);
  for (const ActiveRow& r : active)
    if (!r.bound) is_active[r.index] = true;
  for (int k = 0; k < np; ++k) {
    ParameterSensitivity ps;
    ps.name = targets[k];
    ps.value = ze(n + k);
    ps.derivative = grad_l(n + k);
    ps.relative = e.objective != 0.0 ? ps.value / e.objective * ps.derivative : 0.0;
    const Eigen::VectorXd dz = d.col(k).head(n);
    const Eigen::VectorXd dc = e.inequality_jacobian.topLeftCorner(m, n) * dz + e.inequality_jacobian.block(0, n + k, m, 1);
    for (const double direction : {-1.0, 1.0}) {
      ActiveSetChange& side = direction < 0 ? ps.decrease : ps.increase;
      for (int a = 1; a < na; ++a) {
        const ActiveRow& r = active[a - 1];
        consider(r.sign * r.multiplier, r.sign * d(n + a, k), direction, row_name(r), false, side);
      }
      for (int i = 0; i < m; ++i)
        if (!is_active[i]) consider(std::min(0.0, e.inequalities(i)), dc(i), direction, original.constraint_name(false, i), true, side);
      for (int j = 0; j < n; ++j) {
        const bool bound_active = std::any_of(active.begin(), active.end(), [j](const ActiveRow& r) { return r.bound && r.index == j; });
        if (bound_active) continue;
        if (std::isfinite(upper(j)))
          consider(std::min(0.0, z(j) - upper(j)), dz(j), direction, "upper bound of " + original.variable_name(j), true, side);
        if (std::isfinite(lower(j)))
          consider(std::min(0.0, lower(j) - z(j)), -dz(j), direction, "lower bound of " + original.variable_name(j), true, side);
      }
      if (ps.value != 0.0) side.relative_change /= std::abs(ps.value);
    }
    for (const ActiveSetChange* side : {&ps.decrease, &ps.increase})
      if (side->relative_change < o.kink_range) {
        ps.kink = true;
        if (std::find(ps.weakly_active.begin(), ps.weakly_active.end(), side->constraint) == ps.weakly_active.end())
          ps.weakly_active.push_back(side->constraint);
      }
    out.parameters.push_back(std::move(ps));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace cyclopt::studies
