#include "cyclopt/walker/gait_problem.hpp"

#include "cyclopt/walker/power_kinks.hpp"

#include <limits>
#include <optional>
#include <stdexcept>

namespace cyclopt::walker {


GaitProblem::GaitProblem(const WalkerModel<double>& model, GaitProblemOptions options)
    : model_(model), evaluator_(model), options_(std::move(options)), gait_count_(evaluator_.parameter_count()) {
  parameter_names_ = model_parameter_names(model_);
  if (!(options_.positive_power_band >= 0.0 && options_.positive_power_band <= kMaxPositivePowerBand))
    throw std::invalid_argument("positive_power_band: must be in [0, " + std::to_string(kMaxPositivePowerBand) + "] W");
  if (options_.positive_power_band > 0.0 && options_.quadrature != Quadrature::trapezoid)
    throw std::invalid_argument("positive_power_band: > 0 needs the trapezoid rule (quadrature \"trapezoid\")");
  if (!(options_.positive_power_smoothing >= 0.0 && options_.positive_power_smoothing <= kMaxPositivePowerSmoothing))
    throw std::invalid_argument("positive_power_smoothing: must be in [0, " + std::to_string(kMaxPositivePowerSmoothing) + "] W");
  if (options_.positive_power_smoothing > 0.0 &&
      (options_.quadrature != Quadrature::trapezoid || options_.positive_power_band > 0.0))
    throw std::invalid_argument("positive_power_smoothing: > 0 needs the trapezoid rule and positive_power_band 0");
  bool foot_free = false;
  for (const std::string& name : options_.free_parameters) {
    const int idx = model_parameter_index(model_, name);
    if (follows_foot_geometry(model_, idx))
      throw std::invalid_argument("free parameter '" + name +
                                  "' follows the foot geometry with a density (appendix E); free the foot parameters "
                                  "or the density instead");
    free_indices_.push_back(idx);
    const int f = idx - segment_parameter_count;
    foot_free |= f >= 0 && f < static_cast<int>(model_.foot_parameters.size());
  }
  if (foot_free) {
    const foot::LinearInequalities convexity = foot::convexity_constraints(model_.foot_model);
    const foot::LinearInequalities design = options_.design_bounds
                                                ? foot::design_constraints(model_.foot_model, *options_.design_bounds)
                                                : foot::LinearInequalities{};
    const Eigen::Index rows = convexity.b.size() + design.b.size();
    foot_rows_.A.resize(rows, convexity.A.cols());
    foot_rows_.b.resize(rows);
    foot_rows_.A.topRows(convexity.b.size()) = convexity.A;
    foot_rows_.b.head(convexity.b.size()) = convexity.b;
    for (const std::string& n : convexity.names) foot_rows_.names.push_back("foot convexity: " + n);
    if (design.b.size() > 0) {
      foot_rows_.A.bottomRows(design.b.size()) = design.A;
      foot_rows_.b.tail(design.b.size()) = design.b;
    }
    for (const std::string& n : design.names) foot_rows_.names.push_back("foot design bound (10.1): " + n);
    toe_margin_ = model_.foot_model == foot::FootModel::hmt;
  }
}

int GaitProblem::num_variables() const { return gait_count_ + static_cast<int>(free_indices_.size()); }

int GaitProblem::foot_constraint_count() const { return static_cast<int>(foot_rows_.b.size()) + (toe_margin_ ? 1 : 0); }

int GaitProblem::num_inequalities() const {
  return InequalityLayout{model_.constants.points}.size() + foot_constraint_count();
}

Eigen::VectorXd GaitProblem::lower_bounds() const {
  Eigen::VectorXd l = nlp::Problem::lower_bounds();
  for (std::size_t k = 0; k < free_indices_.size(); ++k) l(gait_count_ + k) = model_parameter_range(model_, free_indices_[k]).first;
  return l;
}

Eigen::VectorXd GaitProblem::upper_bounds() const {
  Eigen::VectorXd u = nlp::Problem::upper_bounds();
  for (std::size_t k = 0; k < free_indices_.size(); ++k) u(gait_count_ + k) = model_parameter_range(model_, free_indices_[k]).second;
  return u;
}

Eigen::VectorXd GaitProblem::initial_point(const Eigen::VectorXd& x) const {
  if (x.size() != gait_count_)
    throw std::invalid_argument("start: " + std::to_string(x.size()) + " gait parameters, expected " +
                                std::to_string(gait_count_));
  Eigen::VectorXd z(num_variables());
  z.head(gait_count_) = x;
  const Eigen::VectorXd p = model_parameters(model_);
  for (std::size_t k = 0; k < free_indices_.size(); ++k) z(gait_count_ + k) = p(free_indices_[k]);
  return z;
}

WalkerModel<double> GaitProblem::model_at(const Eigen::VectorXd& z) const {
  if (free_indices_.empty()) return model_;
  Eigen::VectorXd p = model_parameters(model_);
  for (std::size_t k = 0; k < free_indices_.size(); ++k) p(free_indices_[k]) = z(gait_count_ + k);
  return with_model_parameters<double>(model_, p);
}

GaitOptions gait_options_of(const GaitProblemOptions& p, bool keep_trajectories) {
  GaitOptions o;
  o.objective = p.objective;
  o.speed = p.speed;
  o.quadrature = p.quadrature;
  o.positive_power_band = p.positive_power_band;
  o.positive_power_smoothing = p.positive_power_smoothing;
  o.keep_trajectories = keep_trajectories;
  return o;
}

GaitOptions GaitProblem::gait_options(bool trajectories) const { return gait_options_of(options_, trajectories); }

PeriodicGait<double> GaitProblem::gait_at(const Eigen::VectorXd& z) const {
  const Eigen::VectorXd x = gait_parameters(z);
  if (free_indices_.empty()) return evaluator_.evaluate(x, gait_options(true));
  return GaitEvaluator(model_at(z)).evaluate(x, gait_options(true));
}

double GaitProblem::refined_objective(const Eigen::VectorXd& z, int factor) const {
  if (factor < 1) throw std::invalid_argument("factor: must be >= 1, got " + std::to_string(factor));
  WalkerModel<double> fine = model_at(z);
  fine.constants.points = (fine.constants.points - 1) * factor + 1;
  const PeriodicGait<double> g = GaitEvaluator(fine).evaluate(gait_parameters(z), gait_options(false));
  return g.real ? g.objective : std::numeric_limits<double>::quiet_NaN();
}

nlp::EvaluationStatus GaitProblem::evaluate(const Eigen::VectorXd& z, bool with_derivatives, nlp::Evaluation& out) {
  GaitEvaluation e;
  return evaluate(z, with_derivatives, out, e);
}

nlp::EvaluationStatus GaitProblem::evaluate(const Eigen::VectorXd& z, bool with_derivatives, nlp::Evaluation& out,
                                            GaitEvaluation& e) {
  if (z.size() != num_variables())
    throw std::invalid_argument("z: " + std::to_string(z.size()) + " entries, expected " + std::to_string(num_variables()));
  const Eigen::VectorXd x = gait_parameters(z);
  // With free parameters the model (and its Bezier basis) changes with z; otherwise reuse evaluator_.
  std::optional<GaitEvaluator> local;
  if (!free_indices_.empty()) local.emplace(model_at(z));
  const GaitEvaluator& ev = local ? *local : evaluator_;
  if (with_derivatives) {
    e = ev.evaluate_with_derivatives(x, gait_options(false), free_indices_);
  } else {
    e.gait = ev.evaluate(x, gait_options(false));
  }
  if (!e.gait.real) return nlp::EvaluationStatus::failure(e.gait.failure);
  const int n = num_variables(), nc = static_cast<int>(e.gait.inequalities.size()), nf = foot_constraint_count();
  out.objective = e.gait.objective;
  out.equalities.resize(1);
  out.equalities(0) = e.gait.speed_equality;
  out.inequalities.resize(nc + nf);
  out.inequalities.head(nc) = e.gait.inequalities;
  const int foot_offset = segment_parameter_count;
  const foot::FootParameters<double>& fp = ev.model().foot_parameters;
  if (nf > 0) {
    // A p + b >= 0  ->  -(A p + b) <= 0 (3.21 / 3.24); toe margin > 0 likewise.
    const int rows = static_cast<int>(foot_rows_.b.size());
    out.inequalities.segment(nc, rows) = -(foot_rows_.A * fp + foot_rows_.b);
    if (toe_margin_) out.inequalities(nc + rows) = -foot::toe_convexity_margin(fp);
  }
  if (!with_derivatives) return nlp::EvaluationStatus::success();
  out.gradient = e.derivatives.objective.transpose();
  out.equality_jacobian = e.derivatives.speed_equality;
  out.inequality_jacobian.setZero(nc + nf, n);
  out.inequality_jacobian.topRows(nc) = e.derivatives.inequalities;
  if (nf > 0) {
    const int rows = static_cast<int>(foot_rows_.b.size());
    using D = ad::Dual<foot::kMaxFootParameters>;
    foot::FootParameters<D> fd(fp.size());
    for (int i = 0; i < fp.size(); ++i) fd(i) = D::variable(fp(i), i);
    const D toe = toe_margin_ ? foot::toe_convexity_margin(fd) : D(0.0);
    for (std::size_t k = 0; k < free_indices_.size(); ++k) {
      const int f = free_indices_[k] - foot_offset;
      if (f < 0 || f >= fp.size()) continue;
      out.inequality_jacobian.block(nc, gait_count_ + k, rows, 1) = -foot_rows_.A.col(f);
      if (toe_margin_) out.inequality_jacobian(nc + rows, gait_count_ + k) = -toe.d(f);
    }
  }
  if (declares_kinks()) {
    const double weight_step = ev.model().total_mass * ev.model().constants.gravity * e.gait.step_length;
    out.kinks = mechanical_power_kinks(e.gait.joint_power, e.derivatives.joint_power, e.gait.interval_duration, weight_step);
  } else {
    out.kinks = {};
  }
  // Degenerate feet (an edge of the generating polygon at the ankle vanishing with the whole sole
  // on the ankle's level, section 10.2's stilt) can leave the gait real but its derivatives 0/0:
  // flagged like a gait without a real solution, never passed on as NaN.
  if (!(out.gradient.allFinite() && out.equality_jacobian.allFinite() && out.inequality_jacobian.allFinite()))
    return nlp::EvaluationStatus::failure("non-finite derivatives of the gait at this foot (degenerate geometry)");
  return nlp::EvaluationStatus::success();
}

std::string GaitProblem::variable_name(int i) const {
  if (i < gait_count_) {
    const int nb = model_.joint_count, M = model_.constants.bezier_degree;
    const int coeff = 2 + i / nb, j = i % nb;
    if (coeff == M) {
      static const char* last[] = {"H1-", "H2-", "K1-", "K2-", "F1-", "F2-"};
      return std::string("alpha_tilde_M[") + last[j] + "]";  // eq. (5.55)
    }
    return "alpha_" + std::to_string(coeff) + "[" + joint_name(j) + "]";
  }
  return parameter_names_[free_indices_[i - gait_count_]];
}

std::string GaitProblem::constraint_name(bool equality, int i) const {
  if (equality) return "c_g: mean speed - v_bar (5.103)";
  const InequalityLayout L{model_.constants.points};
  if (i >= L.size()) {
    const int r = i - L.size();
    if (r < static_cast<int>(foot_rows_.names.size())) return foot_rows_.names[r];
    return "foot convexity: HMT toe margin > 0";
  }
  if (i < L.normal_force()) return "impulse (5.104a-b)[" + std::to_string(i) + "]";
  if (i < L.friction()) return "normal force (5.104c)[" + std::to_string(i - L.normal_force()) + "]";
  if (i < L.swing_clearance()) return "friction (5.104d)[" + std::to_string(i - L.friction()) + "]";
  if (i < L.knee_lower()) return "swing clearance (5.104e)[" + std::to_string(i - L.swing_clearance()) + "]";
  if (i < L.knee_upper()) return "knee >= 0 (5.104f)[" + std::to_string(i - L.knee_lower()) + "]";
  if (i < L.torso()) return "knee <= 2pi/3 (5.104g)[" + std::to_string(i - L.knee_upper()) + "]";
  return "torso in [-pi/2, pi/2] (5.104h)[" + std::to_string(i - L.torso()) + "]";
}

}  // namespace cyclopt::walker
