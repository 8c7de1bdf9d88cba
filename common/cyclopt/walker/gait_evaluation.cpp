#include "cyclopt/walker/gait_evaluation.hpp"

#include <stdexcept>
#include <string>

namespace cyclopt::walker {

namespace {

using Dual = ad::Dual<kJacobianChunk>;

void copy_gradient(const Dual& v, int offset, int count, Eigen::RowVectorXd& row) {
  row.segment(offset, count) = v.d.head(count).transpose();
}

}  // namespace

GaitEvaluator::GaitEvaluator(WalkerModel<double> model)
    : model_(std::move(model)), basis_(bezier_basis(model_.constants.bezier_degree, model_.constants.points)) {}

PeriodicGait<double> GaitEvaluator::evaluate(const Eigen::VectorXd& x, const GaitOptions& options) const {
  if (x.size() != parameter_count())
    throw std::invalid_argument("x: " + std::to_string(x.size()) + " entries, expected " + std::to_string(parameter_count()));
  return periodic_gait(model_, basis_, x, options);
}

GaitEvaluation GaitEvaluator::evaluate_with_derivatives(const Eigen::VectorXd& x, const GaitOptions& options,
                                                        const std::vector<int>& parameter_indices) const {
  GaitEvaluation out;
  out.gait = evaluate(x, options);
  if (!out.gait.real) return out;
  const int nx = parameter_count(), np = static_cast<int>(parameter_indices.size()), n = nx + np;
  const Eigen::VectorXd p0 = model_parameters(model_);
  for (int idx : parameter_indices)
    if (idx < 0 || idx >= p0.size())
      throw std::invalid_argument("parameter index " + std::to_string(idx) + " outside [0, " + std::to_string(p0.size() - 1) + "]");
  GaitDerivatives& d = out.derivatives;
  for (Eigen::RowVectorXd* row : {&d.objective, &d.f_mech, &d.f_usq, &d.speed_equality, &d.step_length, &d.step_period,
                                  &d.mean_speed, &d.floquet})
    row->setZero(n);
  d.inequalities.setZero(out.gait.inequalities.size(), n);
  GaitOptions light = options;
  light.keep_trajectories = false;
  const WalkerModel<Dual> plain_model = cast_model<Dual>(model_);
  for (int start = 0; start < n; start += kJacobianChunk) {
    const int count = std::min(kJacobianChunk, n - start);
    Eigen::Matrix<Dual, Eigen::Dynamic, 1> xd(nx);
    for (int i = 0; i < nx; ++i) xd(i) = Dual(x(i));
    bool seeds_parameters = false;
    Eigen::Matrix<Dual, Eigen::Dynamic, 1> pd(p0.size());
    for (int i = 0; i < p0.size(); ++i) pd(i) = Dual(p0(i));
    for (int k = 0; k < count; ++k) {
      const int dir = start + k;
      if (dir < nx) {
        xd(dir).d(k) = 1.0;
      } else {
        pd(parameter_indices[dir - nx]).d(k) = 1.0;
        seeds_parameters = true;
      }
    }
    const PeriodicGait<Dual> gd = seeds_parameters ? periodic_gait(with_model_parameters<Dual>(model_, pd), basis_, xd, light)
                                                   : periodic_gait(plain_model, basis_, xd, light);
    if (!gd.real) throw std::logic_error("derivative pass disagrees with value pass: " + gd.failure);
    copy_gradient(gd.objective, start, count, d.objective);
    copy_gradient(gd.f_mech, start, count, d.f_mech);
    copy_gradient(gd.f_usq, start, count, d.f_usq);
    copy_gradient(gd.speed_equality, start, count, d.speed_equality);
    copy_gradient(gd.step_length, start, count, d.step_length);
    copy_gradient(gd.step_period, start, count, d.step_period);
    copy_gradient(gd.mean_speed, start, count, d.mean_speed);
    copy_gradient(gd.floquet, start, count, d.floquet);
    for (int r = 0; r < gd.inequalities.size(); ++r)
      d.inequalities.block(r, start, 1, count) = gd.inequalities(r).d.head(count).transpose();
  }
  out.has_derivatives = true;
  return out;
}

}  // namespace cyclopt::walker
