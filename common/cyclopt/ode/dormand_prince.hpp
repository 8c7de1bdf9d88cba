#pragma once
// Adaptive explicit Runge-Kutta integration with the Dormand-Prince 5(4) pair (FSAL, local
// extrapolation, 4th-order continuous extension) and location of one terminal event g(t, y) = 0.
// Used as the independent reference of the semi-analytic gait (walker/forward_simulation.hpp).
//
// Error control: per component |err_i| <= atol + rtol max(|y_i|, |y_new,i|), RMS norm, step factor
// 0.9 (1/err)^(1/5) limited to [0.2, 5]. An event is a sign change of g from > 0 to <= 0 between two
// accepted steps; it is bracketed on the continuous extension, refined by the Illinois method, and
// the final state is recomputed by one exact Runge-Kutta step from the last accepted point.

#include <Eigen/Core>

#include <functional>
#include <limits>
#include <string>

namespace cyclopt::ode {

using RightHandSide = std::function<void(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy)>;
using EventFunction = std::function<double(double t, const Eigen::VectorXd& y)>;

struct IntegratorOptions {
  double relative_tolerance = 1e-10;
  double absolute_tolerance = 1e-12;
  double initial_step = 1e-4;
  double max_step = std::numeric_limits<double>::infinity();
  int max_steps = 1000000;
  double event_tolerance = 1e-14;  // on t
};

struct IntegrationResult {
  bool ok = false;        // reached t_end or the event
  bool event = false;     // stopped at the event
  double t = 0.0;
  Eigen::VectorXd y;
  int steps = 0;
  int rejected_steps = 0;
  int evaluations = 0;    // right-hand side calls
  std::string message;
};

// Integrates y' = f(t, y) from (t0, y0) until t_end or, if `event` is set, the first crossing of
// event(t, y) from positive to non-positive.
IntegrationResult integrate(const RightHandSide& f, double t0, const Eigen::VectorXd& y0, double t_end,
                            const IntegratorOptions& options, const EventFunction& event = {});

}  // namespace cyclopt::ode
