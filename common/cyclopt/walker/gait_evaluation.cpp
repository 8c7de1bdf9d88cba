#include "cyclopt/walker/gait_evaluation.hpp"

#include "cyclopt/nlp/spare_core.hpp"

#include <mutex>
#include <stdexcept>
#include <string>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace cyclopt::walker {

namespace {

template <int N>
void copy_gradient(const ad::Dual<N>& v, int offset, int count, Eigen::RowVectorXd& row) {
  row.segment(offset, count) = v.d.head(count).transpose();
}

// One forward-mode pass: seeds the directions start .. start+count-1 of [x; p_mod(parameter_indices)]
// into Dual<N> and stores their derivative columns. The model is cast to Dual only where a model
// parameter is seeded or the reference path asks for it; otherwise its constants stay double.
// Returns false with *failure set when the Dual evaluation finds no real gait where the double one
// did: at the boundary of existence a test such as (5.47) can fall the other way by rounding.
template <int N>
bool derivative_pass(const WalkerModel<double>& model, const BezierBasis& basis, const Eigen::VectorXd& x,
                     const std::vector<int>& parameter_indices, const GaitOptions& options, int start, int count,
                     bool dual_model, GaitDerivatives& d, std::string* failure) {
  using Dual = ad::Dual<N>;
  const int nx = static_cast<int>(x.size());
  Vector<Dual> xd(nx);
  for (int i = 0; i < nx; ++i) xd(i) = Dual(x(i));
  std::vector<std::pair<int, int>> seeded_parameters;  // (direction k, index into p_mod)
  for (int k = 0; k < count; ++k) {
    const int dir = start + k;
    if (dir < nx) xd(dir).d(k) = 1.0;
    else seeded_parameters.emplace_back(k, parameter_indices[dir - nx]);
  }
  PeriodicGait<Dual> gd;
  if (!seeded_parameters.empty()) {
    const Eigen::VectorXd p0 = model_parameters(model);
    Vector<Dual> pd(p0.size());
    for (int i = 0; i < p0.size(); ++i) pd(i) = Dual(p0(i));
    for (const auto& [k, idx] : seeded_parameters) pd(idx).d(k) = 1.0;
    gd = periodic_gait(with_model_parameters<Dual>(model, pd), basis, xd, options);
  } else if (dual_model) {
    gd = periodic_gait(cast_model<Dual>(model), basis, xd, options);
  } else {
    gd = periodic_gait(model, basis, xd, options);
  }
  if (!gd.real) {
    *failure = gd.failure;
    return false;
  }
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
  const Eigen::Index points = gd.joint_power.cols();
  for (Eigen::Index j = 0; j < gd.joint_power.rows(); ++j)
    for (Eigen::Index i = 0; i < points; ++i)
      d.joint_power.block(j * points + i, start, 1, count) = gd.joint_power(j, i).d.head(count).transpose();
  return true;
}

// A derivative pass allocates and frees ~6 MB of Dual arrays (P = 200, 30 directions). With glibc's
// default thresholds those blocks are mapped afresh or trimmed back to the kernel on every call, and
// refaulting the pages cost more than the arithmetic (measured: 7.3 ms -> 3.0 ms per HM Jacobian).
// So the process keeps up to 64 MB of freed heap and serves blocks below 32 MB from it. Set once.
void keep_freed_heap_for_derivative_passes() {
#ifdef __GLIBC__
  static std::once_flag once;
  std::call_once(once, [] {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 64 << 20);
  });
#endif
}

}  // namespace

GaitEvaluator::GaitEvaluator(WalkerModel<double> model)
    : model_(std::move(model)), basis_(bezier_basis(model_.constants.bezier_degree, model_.constants.points)) {
  keep_freed_heap_for_derivative_passes();
}

PeriodicGait<double> GaitEvaluator::evaluate(const Eigen::VectorXd& x, const GaitOptions& options) const {
  if (x.size() != parameter_count())
    throw std::invalid_argument("x: " + std::to_string(x.size()) + " entries, expected " + std::to_string(parameter_count()));
  return periodic_gait(model_, basis_, x, options);
}

GaitEvaluation GaitEvaluator::evaluate_with_derivatives(const Eigen::VectorXd& x, const GaitOptions& options,
                                                        const std::vector<int>& parameter_indices) const {
  return derivatives(x, options, parameter_indices, DerivativePath::fast);
}

GaitEvaluation GaitEvaluator::evaluate_with_reference_derivatives(const Eigen::VectorXd& x, const GaitOptions& options,
                                                                  const std::vector<int>& parameter_indices) const {
  return derivatives(x, options, parameter_indices, DerivativePath::reference);
}

GaitEvaluation GaitEvaluator::derivatives(const Eigen::VectorXd& x, const GaitOptions& options,
                                          const std::vector<int>& parameter_indices, DerivativePath path) const {
  GaitEvaluation out;
  out.gait = evaluate(x, options);
  if (!out.gait.real) return out;
  const int nx = parameter_count(), np = static_cast<int>(parameter_indices.size()), n = nx + np;
  const int p_count = model_parameter_count(model_);
  for (int idx : parameter_indices)
    if (idx < 0 || idx >= p_count)
      throw std::invalid_argument("parameter index " + std::to_string(idx) + " outside [0, " + std::to_string(p_count - 1) + "]");
  GaitDerivatives& d = out.derivatives;
  for (Eigen::RowVectorXd* row : {&d.objective, &d.f_mech, &d.f_usq, &d.speed_equality, &d.step_length, &d.step_period,
                                  &d.mean_speed, &d.floquet})
    row->setZero(n);
  d.inequalities.setZero(out.gait.inequalities.size(), n);
  d.joint_power.setZero(out.gait.joint_power.size(), n);
  GaitOptions light = options;
  light.keep_trajectories = false;
  const bool reference = path == DerivativePath::reference;
  // One pass carrying all directions for the default Bezier degree M = 6 (point feet 20, feet 30),
  // in Dual<N> padded to a multiple of 8 (the padding directions stay zero): each derivative
  // operation is then whole registers (4 doubles with the default x86-64-v3, 8 with AVX-512 in a
  // CYCLOPT_ARCH=native build).
  // The chunks of the other paths are shared out between two threads when a core is spare (a
  // continuation run with free foot parameters, a multistart's last run: nlp/spare_core.hpp); each
  // chunk is the same pass in either thread, so the Jacobian is bitwise the same. (The one pass is
  // not split: two Dual<16> passes differ from it by rounding - Eigen blocks its products by the
  // scalar's size - and a solve's path may follow rounding.)
  std::string failure;
  bool real = true;
  if (!reference && np == 0 && nx == 20) {
    real = derivative_pass<24>(model_, basis_, x, parameter_indices, light, 0, n, false, d, &failure);
  } else if (!reference && np == 0 && nx == 30) {
    real = derivative_pass<32>(model_, basis_, x, parameter_indices, light, 0, n, false, d, &failure);
  } else {
    std::string failures[2];  // of this thread's chunks and the helper's
    bool reals[2] = {true, true};
    nlp::split_on_spare_core((n + kJacobianChunk - 1) / kJacobianChunk, 2, [&](int begin, int end, bool helper) {
      for (int c = begin; c < end && reals[helper]; ++c)
        reals[helper] = derivative_pass<kJacobianChunk>(model_, basis_, x, parameter_indices, light, c * kJacobianChunk,
                                                        std::min(kJacobianChunk, n - c * kJacobianChunk), reference, d,
                                                        &failures[helper]);
    });
    real = reals[0] && reals[1];
    failure = reals[0] ? failures[1] : failures[0];  // the first failing chunk's, as in one thread
  }
  if (!real) {  // treated like a value pass without a gait: the caller backtracks or stops
    out.gait.real = false;
    out.gait.failure = "on the boundary of existence, the derivative pass finds: " + failure;
    return out;
  }
  out.has_derivatives = true;
  return out;
}

Eigen::MatrixXd GaitDerivatives::stacked() const {
  Eigen::MatrixXd J(8 + inequalities.rows(), objective.size());
  J << objective, f_mech, f_usq, speed_equality, step_length, step_period, mean_speed, floquet, inequalities;
  return J;
}

}  // namespace cyclopt::walker
