#include "cyclopt/walker/starting_gait.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace cyclopt::walker {

namespace {

// Weight of the speed residual (m/s) against the scaled inequalities: the speed is an equality
// and must end up exact.
constexpr double kSpeedWeight = 10.0;

struct Candidate {
  GaitShape shape;
  Eigen::VectorXd x;
  double merit;
};

std::vector<GaitShape> template_grid(bool feet) {
  std::vector<GaitShape> grid;
  for (double d = 0.25; d < 0.9; d += 0.1)
    for (double lean : {0.0, 0.1, 0.2, 0.3})
      for (double bump : {0.3, 0.6})
        for (double push : feet ? std::vector<double>{1.0, 1.5} : std::vector<double>{1.0}) {
          GaitShape s;
          s.contact_distance = d;
          s.torso_lean = lean;
          s.swing_knee_bump = bump;
          s.push_off_rate = push;
          grid.push_back(s);
        }
  return grid;
}

double violation_norm2(const Eigen::VectorXd& c, double margin) {
  return (c.array() + margin).max(0.0).square().sum();
}

// Minimum-norm Newton steps on c_g alone (eq. 5.103), which Levenberg-Marquardt leaves at ~1e-6
// when inequalities are nearly active; the inequality margin absorbs the tiny change in x.
void polish_speed(const GaitEvaluator& ev, const GaitOptions& gopt, Eigen::VectorXd& x, int& evaluations) {
  for (int it = 0; it < 5; ++it) {
    ++evaluations;
    const GaitEvaluation e = ev.evaluate_with_derivatives(x, gopt);
    if (!e.gait.real || std::abs(e.gait.speed_equality) <= 1e-12) return;
    const Eigen::RowVectorXd& g = e.derivatives.speed_equality;
    const Eigen::VectorXd step = -g.transpose() * (e.gait.speed_equality / g.squaredNorm());
    ++evaluations;
    if (!ev.evaluate(x + step, gopt).real) return;
    x += step;
  }
}

}  // namespace

StartingGait starting_gait(const GaitEvaluator& ev, const StartingGaitOptions& o) {
  if (!(o.speed >= 0.05 && o.speed <= 5.0))
    throw std::invalid_argument("speed: " + std::to_string(o.speed) + " m/s outside [0.05, 5]");
  StartingGait out;
  GaitOptions gopt;
  gopt.speed = o.speed;
  gopt.keep_trajectories = false;

  std::vector<Candidate> candidates;
  for (const GaitShape& s : template_grid(ev.model().has_feet())) {
    Eigen::VectorXd x;
    try {
      x = gait_parameters(ev.model(), s);
    } catch (const std::invalid_argument&) {
      continue;  // no posture for this template
    }
    ++out.evaluations;
    const PeriodicGait<double> g = ev.evaluate(x, gopt);
    if (!g.real) continue;
    candidates.push_back({s, x, g.speed_equality * g.speed_equality + violation_norm2(g.inequalities, o.margin)});
  }
  if (candidates.empty()) {
    out.message = "no template gait has a real periodic solution";
    return out;
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.merit < b.merit; });

  // Residuals r = [c_g; max(c_u + margin, 0)], Jacobian rows of the active inequalities.
  const nlp::ResidualFunction residual = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    ++out.evaluations;
    if (!J) {
      const PeriodicGait<double> g = ev.evaluate(x, gopt);
      if (!g.real) return false;
      r.resize(1 + g.inequalities.size());
      r(0) = kSpeedWeight * g.speed_equality;
      r.tail(g.inequalities.size()) = (g.inequalities.array() + o.margin).max(0.0).matrix();
      return true;
    }
    const GaitEvaluation e = ev.evaluate_with_derivatives(x, gopt);
    if (!e.gait.real) return false;
    const Eigen::VectorXd& c = e.gait.inequalities;
    r.resize(1 + c.size());
    J->resize(1 + c.size(), x.size());
    r(0) = kSpeedWeight * e.gait.speed_equality;
    J->row(0) = kSpeedWeight * e.derivatives.speed_equality;
    for (int i = 0; i < c.size(); ++i) {
      const bool active = c(i) + o.margin > 0.0;
      r(1 + i) = active ? c(i) + o.margin : 0.0;
      if (active) J->row(1 + i) = e.derivatives.inequalities.row(i);
      else J->row(1 + i).setZero();
    }
    return true;
  };

  double best_merit = std::numeric_limits<double>::infinity();
  const int tries = std::min<int>(o.max_candidates, static_cast<int>(candidates.size()));
  for (int k = 0; k < tries; ++k) {
    Eigen::VectorXd x = candidates[k].x;
    const nlp::LeastSquaresSummary ls = nlp::levenberg_marquardt(residual, x, o.least_squares);
    polish_speed(ev, gopt, x, out.evaluations);
    ++out.evaluations;
    PeriodicGait<double> g = ev.evaluate(x, GaitOptions{gopt.objective, o.speed, true});
    if (!g.real) continue;
    const double merit = g.speed_equality * g.speed_equality + violation_norm2(g.inequalities, 0.0);
    if (merit < best_merit) {
      best_merit = merit;
      out.real = true;
      out.x = x;
      out.shape = candidates[k].shape;
      out.speed_error = g.speed_equality;
      out.max_violation = g.inequalities.maxCoeff();
      out.feasible = std::abs(out.speed_error) <= 1e-8 && out.max_violation <= 0.0;
      out.gait = std::move(g);
      out.message = "template " + std::to_string(k + 1) + " of " + std::to_string(candidates.size()) + " real; " +
                    ls.message + " after " + std::to_string(ls.iterations) + " Levenberg-Marquardt iterations";
    }
    if (out.feasible) break;
  }
  if (!out.real) out.message = "no template kept a real solution during feasibility restoration";
  return out;
}

GaitStart gait_start(const GaitEvaluator& ev, double speed, const std::optional<Eigen::VectorXd>& given) {
  if (given) return {*given, "given"};
  StartingGaitOptions o;
  o.speed = speed;
  const StartingGait sg = starting_gait(ev, o);
  if (!sg.real) throw std::runtime_error("no starting gait at " + std::to_string(speed) + " m/s: " + sg.message);
  return {sg.x, "automatic starting gait (" + sg.message + ")"};
}

Eigen::VectorXd perturbed_gait(const GaitEvaluator& ev, const Eigen::VectorXd& x, double scale, std::mt19937_64& rng,
                               int max_draws) {
  std::normal_distribution<double> normal(0.0, 1.0);
  GaitOptions gopt;
  gopt.keep_trajectories = false;
  for (int draw = 0; draw < max_draws; ++draw) {
    Eigen::VectorXd y = x;
    for (int i = 0; i < y.size(); ++i) y(i) += scale * normal(rng);
    if (ev.evaluate(y, gopt).real) return y;
  }
  throw std::runtime_error("perturbation scale: " + std::to_string(scale) + " rad gives no real periodic solution in " +
                           std::to_string(max_draws) + " draws; use a smaller scale");
}

}  // namespace cyclopt::walker
