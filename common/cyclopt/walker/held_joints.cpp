#include "cyclopt/walker/held_joints.hpp"

#include "cyclopt/autodiff/dual.hpp"
#include "cyclopt/walker/positive_power.hpp"
#include "cyclopt/walker/virtual_constraints.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cyclopt::walker {

namespace {

constexpr int kDirections = 32;  // Dual width: the 30 gait parameters of a walker with feet (20 without)

}  // namespace

std::vector<int> held_joints(const PeriodicGait<double>& gait, double still_ratio) {
  if (!(still_ratio > 0.0 && still_ratio < 1.0)) throw std::invalid_argument("still_ratio: must be in (0, 1)");
  std::vector<int> held;
  if (!gait.real || gait.trajectory.q_dot.cols() == 0) return held;
  // q_dot's first row is theta's; the joints follow.
  const Eigen::VectorXd speed = gait.trajectory.q_dot.bottomRows(gait.trajectory.q_dot.rows() - 1).cwiseAbs().rowwise().maxCoeff();
  const double fastest = speed.maxCoeff();
  for (Eigen::Index j = 0; j < speed.size(); ++j)
    if (speed(j) <= still_ratio * fastest) held.push_back(static_cast<int>(j));
  return held;
}

HeldJointProblem::HeldJointProblem(const WalkerModel<double>& model, const GaitProblemOptions& options, std::vector<int> joints)
    : model_(model), gait_(model, options), joints_(std::move(joints)) {
  if (!gait_.declares_kinks())
    throw std::invalid_argument("objective: held joints need f_mech by the seed's rule (no band, no smoothing)");
  if (!options.free_parameters.empty())
    throw std::invalid_argument("free_parameters: held joints need a gait problem without free model parameters");
  if (gait_.num_variables() > kDirections)
    throw std::invalid_argument("bezier_degree: held joints support at most " + std::to_string(kDirections) + " gait parameters");
  for (int j : joints_)
    if (j < 0 || j >= model_.joint_count)
      throw std::invalid_argument("joints: " + std::to_string(j) + " outside [0, " + std::to_string(model_.joint_count) + ")");
}

int HeldJointProblem::num_equalities() const {
  return gait_.num_equalities() + model_.constants.bezier_degree * static_cast<int>(joints_.size());
}

// f_mech without the held joints' terms dt_i g(p_i, p_i+1) / (m g L) (5.100-5.102): on the manifold
// they vanish identically, off it their kinks are all they add - their gradients flip between
// iterates and spoil the Hessian model. g is positively homogeneous of degree 1, so the kinked terms'
// slopes (power_kinks.hpp) times the powers' gradients are the terms' gradient but for
// g * grad(dt_i / m g L), which vanishes with the powers on the manifold.
void HeldJointProblem::leave_out_held_powers(const PeriodicGait<double>& gait, nlp::Evaluation& out) const {
  const Eigen::MatrixXd& p = gait.joint_power;
  const Eigen::Index points = p.cols();
  double held = 0.0;
  for (int j : joints_)
    for (Eigen::Index i = 0; i + 1 < points; ++i) held += positive_part_trapezoid(p(j, i), p(j, i + 1), gait.interval_duration(i));
  out.objective -= held / (model_.total_mass * model_.constants.gravity * gait.step_length);
  if (out.kinks.empty()) return;
  std::vector<nlp::KinkedTerm> kept;
  for (const nlp::KinkedTerm& t : out.kinks.terms) {
    if (std::find(joints_.begin(), joints_.end(), static_cast<int>(t.sample / points)) == joints_.end()) {
      kept.push_back(t);
      continue;
    }
    out.gradient -= t.slope * out.kinks.jacobian.row(t.sample).transpose();
  }
  out.kinks.terms = std::move(kept);
}

nlp::EvaluationStatus HeldJointProblem::evaluate(const Eigen::VectorXd& z, bool with_derivatives, nlp::Evaluation& out) {
  GaitEvaluation ge;
  const nlp::EvaluationStatus status = gait_.evaluate(z, with_derivatives, out, ge);
  if (!status.ok) return status;
  leave_out_held_powers(ge.gait, out);
  using Dual = ad::Dual<kDirections>;
  const int n = num_variables(), M = model_.constants.bezier_degree, m0 = gait_.num_equalities();
  Eigen::Matrix<Dual, Eigen::Dynamic, 1> x(n);
  for (int i = 0; i < n; ++i) {
    x(i) = Dual(z(i));
    x(i).d(i) = 1.0;
  }
  const VirtualConstraints<Dual> vc = virtual_constraints(model_, x);
  if (!vc.ok) return nlp::EvaluationStatus::failure(vc.failure);
  out.equalities.conservativeResize(num_equalities());  // the speed equality's rows stay on top
  if (with_derivatives) out.equality_jacobian.conservativeResize(num_equalities(), n);
  int row = m0;
  for (int j : joints_)
    for (int i = 0; i < M; ++i, ++row) {
      const Dual difference = vc.alpha(j, i + 1) - vc.alpha(j, i);
      out.equalities(row) = difference.v;
      if (with_derivatives) out.equality_jacobian.row(row) = difference.d.head(n).transpose();
    }
  return nlp::EvaluationStatus::success();
}

std::string HeldJointProblem::constraint_name(bool equality, int i) const {
  const int m0 = gait_.num_equalities(), M = model_.constants.bezier_degree;
  if (!equality || i < m0) return gait_.constraint_name(equality, i);
  const int k = i - m0;
  return std::string("held joint ") + joint_name(joints_[static_cast<size_t>(k / M)]) + ": alpha_" +
         std::to_string(k % M + 1) + " - alpha_" + std::to_string(k % M);
}

}  // namespace cyclopt::walker
