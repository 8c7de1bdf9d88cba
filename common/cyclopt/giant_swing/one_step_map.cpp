#include "cyclopt/giant_swing/one_step_map.hpp"

#include "cyclopt/autodiff/dual.hpp"

#include <Eigen/Eigenvalues>

#include <array>

namespace cyclopt::giant_swing {
namespace {

// Section coordinates (phi', alpha, alpha') inside the state (phi, alpha, phi', alpha').
constexpr std::array<int, 3> kSectionIndex = {state_index::phi_rate, state_index::alpha, state_index::alpha_rate};

}  // namespace

OneStep one_step_map(const Model& model, const HipTorqueLaw& torque, const SectionState& s,
                     const SimulationOptions& options) {
  const SimulationResult r = simulate_swings(model, torque, state_on_section(s), 1, options);
  OneStep out;
  out.stats = r.stats;
  out.ok = !r.failed;
  if (out.ok) {
    out.round = r.rounds[0];
    out.next = SectionState(out.round.phi_rate, out.round.alpha, out.round.alpha_rate);
  }
  return out;
}

OneStepJacobian one_step_jacobian(const Model& model, const HipTorqueLaw& torque, const SectionState& s,
                                  const SimulationOptions& options) {
  using Y = Eigen::Matrix<double, 20, 1>;
  using D = ad::Dual<4>;
  auto flow_and_jacobian = [&](const State<double>& x, Eigen::Matrix4d& A) {
    State<D> xd;
    for (int i = 0; i < 4; ++i) xd[i] = D::variable(x[i], i);
    const State<D> fd = state_derivative(model, xd, torque(xd));
    State<double> f;
    for (int i = 0; i < 4; ++i) f[i] = fd[i].v, A.row(i) = fd[i].d.transpose();
    return f;
  };
  auto rhs = [&](double, const Y& y) {
    Eigen::Matrix4d A;
    const State<double> f = flow_and_jacobian(y.head<4>(), A);
    Y dy;
    dy.head<4>() = f;
    Eigen::Map<Eigen::Matrix4d>(dy.data() + 4) = A * Eigen::Map<const Eigen::Matrix4d>(y.data() + 4);
    return dy;
  };
  auto events = [&](double, const Y& y) { return Eigen::Vector2d(kTwoPi - y[0], y[2]); };  // 2 pi reached, phi' <= 0
  Y y0;
  y0.head<4>() = state_on_section(s);
  Eigen::Map<Eigen::Matrix4d>(y0.data() + 4).setIdentity();
  const auto r = ode::integrate(rhs, 0.0, y0, options.max_round_time, options.integrator, events);
  OneStepJacobian out;
  out.stats = r.stats;
  out.ok = r.status == ode::IntegrationStatus::event && r.event_index == 0;
  if (!out.ok) return out;
  const State<double> xT = r.y.head<4>();
  Eigen::Matrix4d A;
  const State<double> fT = flow_and_jacobian(xT, A);
  const Eigen::Matrix4d Phi = Eigen::Map<const Eigen::Matrix4d>(r.y.data() + 4);
  // Stop at phi = 2 pi instead of at t = T: project along the flow (the time of arrival varies).
  const Eigen::Matrix4d projected = (Eigen::Matrix4d::Identity() - fT * Eigen::RowVector4d::Unit(0) / fT[0]) * Phi;
  for (int i = 0; i < 3; ++i) {
    out.next[i] = xT[kSectionIndex[i]];
    for (int j = 0; j < 3; ++j) out.jacobian(i, j) = projected(kSectionIndex[i], kSectionIndex[j]);
  }
  return out;
}

Eigen::Matrix3d one_step_jacobian_by_differences(const Model& model, const HipTorqueLaw& torque,
                                                 const SectionState& s, const SimulationOptions& options,
                                                 double relative_step) {
  Eigen::Matrix3d J;
  for (int j = 0; j < 3; ++j) {
    const double h = relative_step * (1.0 + std::abs(s[j]));
    SectionState plus = s, minus = s;
    plus[j] += h;
    minus[j] -= h;
    J.col(j) = (one_step_map(model, torque, plus, options).next - one_step_map(model, torque, minus, options).next) /
               (2.0 * h);
  }
  return J;
}

Eigen::Vector3cd floquet_multipliers(const Eigen::Matrix3d& jacobian) {
  return Eigen::EigenSolver<Eigen::Matrix3d>(jacobian, false).eigenvalues();
}

}  // namespace cyclopt::giant_swing
