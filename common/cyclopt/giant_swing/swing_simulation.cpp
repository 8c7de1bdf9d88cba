#include "cyclopt/giant_swing/swing_simulation.hpp"

#include <cmath>

namespace cyclopt::giant_swing {

double hip_jerk(const Model& model, const HipTorqueLaw& torque, const State<double>& x) {
  using D = ad::Dual<1>;
  const State<double> xdot = state_derivative(model, x, torque(x));
  State<D> xd;
  for (int i = 0; i < 4; ++i) xd[i] = D(x[i], D::Gradient::Constant(xdot[i]));
  return accelerations(model, xd, torque(xd)).qdd[1].d[0];
}

SimulationResult simulate_swings(const Model& model, const HipTorqueLaw& torque, const State<double>& x0, int rounds,
                                 const SimulationOptions& options,
                                 const std::function<void(double, const AugmentedState&)>& observe) {
  const AdmissibleRanges& ranges = options.ranges;
  auto rhs = [&](double, const AugmentedState& y) {
    const State<double> x = y.head<4>();
    const double M_alpha = torque(x);
    const Accelerations<double> a = accelerations(model, x, M_alpha);
    const double jerk = hip_jerk(model, torque, x);
    AugmentedState dy;
    dy << x[2], x[3], a.qdd[0], a.qdd[1], -a.friction_moment * x[2], 0.5 * jerk * jerk, 0.5 * M_alpha * M_alpha;
    return dy;
  };
  SimulationResult result;
  AugmentedState y = AugmentedState::Zero();
  y.head<4>() = x0;
  double t = 0.0;
  static const char* const reasons[] = {"", "phi' reached 0 (motion reversed)", "alpha below alpha_min",
                                        "alpha above alpha_max", "|alpha''| above its limit"};
  for (int n = 1; n <= rounds; ++n) {
    const double phi_end = kTwoPi * n;
    auto events = [&](double, const AugmentedState& s) {
      Eigen::Matrix<double, 5, 1> g;
      const State<double> x = s.head<4>();
      g[0] = phi_end - x[0];
      g[1] = x[2];
      g[2] = x[1] - ranges.alpha_min;
      g[3] = ranges.alpha_max - x[1];
      g[4] = std::isfinite(ranges.alpha_acceleration_max)
                 ? ranges.alpha_acceleration_max - std::abs(accelerations(model, x, torque(x)).qdd[1])
                 : 1.0;
      return g;
    };
    auto forward = [&](double time, const AugmentedState& s) {
      if (observe) observe(time, s);
    };
    const AugmentedState y_start = y;
    const double t_start = t;
    const auto r = ode::integrate(rhs, t, y, t + options.max_round_time, options.integrator, events, forward);
    result.stats.accepted_steps += r.stats.accepted_steps;
    result.stats.rejected_steps += r.stats.rejected_steps;
    result.stats.rhs_evaluations += r.stats.rhs_evaluations;
    y = r.y;
    t = r.t;
    if (r.status != ode::IntegrationStatus::event || r.event_index != 0) {
      result.failed = true;
      result.failure_phi = y[0];
      result.failure_reason = r.status == ode::IntegrationStatus::event ? reasons[r.event_index]
                              : r.status == ode::IntegrationStatus::reached_end
                                  ? "round took longer than max_round_time"
                                  : "integrator failed (step size underflow, too many steps or non-finite state)";
      return result;
    }
    RoundResult round;
    round.phi_rate = y[2];
    round.alpha = y[1];
    round.alpha_rate = y[3];
    round.duration = t - t_start;
    round.friction_loss = y[4] - y_start[4];
    round.jerk = y[5] - y_start[5];
    round.torque_integral = y[6] - y_start[6];
    result.rounds.push_back(round);
  }
  return result;
}

}  // namespace cyclopt::giant_swing
