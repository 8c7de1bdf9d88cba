#pragma once
// Adaptive Cash-Karp Runge-Kutta integration (embedded 4th/5th order pair) with event location.
//
// The seed's integrator (seed 000, appendix C.3: rkck/rkqs/odeint from Numerical Recipes) steps
// the 5th-order solution and controls the step with the embedded 4th-order error estimate. This
// is the same scheme with a mixed absolute/relative error norm and terminal events:
//
//   events(t, y) returns a vector g; an event fires when a component goes from g_i > 0 to
//   g_i <= 0 within an accepted step. The crossing is located by Illinois regula falsi on the
//   step length, re-taking one Cash-Karp step of the trial length from the start of the step
//   (5th-order accurate, no dense output needed). Integration stops at the earliest crossing.
//
// cash_karp_step() is templated on the state type so it also runs on ad::Dual states (fixed
// step sizes: exact derivatives of the discrete scheme); integrate() is for double states.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cyclopt::ode {

struct CashKarpOptions {
  double relative_tolerance = 1e-10;
  double absolute_tolerance = 1e-12;
  double initial_step = 1e-3;
  double max_step = std::numeric_limits<double>::infinity();
  double min_step = 1e-13;       // below this the integration fails (step-size underflow)
  int max_steps = 1000000;       // accepted + rejected
  double event_time_tolerance = 1e-14;
};

enum class IntegrationStatus { reached_end, event, step_size_underflow, too_many_steps, non_finite };

struct IntegrationStats {
  int accepted_steps = 0;
  int rejected_steps = 0;
  int rhs_evaluations = 0;
};

template <class Vector>
struct IntegrationResult {
  IntegrationStatus status = IntegrationStatus::reached_end;
  int event_index = -1;  // which component of g fired (status == event)
  double t = 0.0;
  Vector y;
  IntegrationStats stats;
};

// Cash-Karp tableau (Numerical Recipes 16.2, as in seed 000 appendix C.3).
namespace cash_karp_tableau {
inline constexpr double a2 = 0.2, a3 = 0.3, a4 = 0.6, a5 = 1.0, a6 = 0.875;
inline constexpr double b21 = 0.2;
inline constexpr double b31 = 3.0 / 40.0, b32 = 9.0 / 40.0;
inline constexpr double b41 = 0.3, b42 = -0.9, b43 = 1.2;
inline constexpr double b51 = -11.0 / 54.0, b52 = 2.5, b53 = -70.0 / 27.0, b54 = 35.0 / 27.0;
inline constexpr double b61 = 1631.0 / 55296.0, b62 = 175.0 / 512.0, b63 = 575.0 / 13824.0,
                        b64 = 44275.0 / 110592.0, b65 = 253.0 / 4096.0;
inline constexpr double c1 = 37.0 / 378.0, c3 = 250.0 / 621.0, c4 = 125.0 / 594.0, c6 = 512.0 / 1771.0;
inline constexpr double dc1 = c1 - 2825.0 / 27648.0, dc3 = c3 - 18575.0 / 48384.0, dc4 = c4 - 13525.0 / 55296.0,
                        dc5 = -277.0 / 14336.0, dc6 = c6 - 0.25;
}  // namespace cash_karp_tableau

// One step of length h from (t, y) with slope dydt = f(t, y): the 5th-order solution y_out and
// the difference to the embedded 4th-order solution, err. Costs 5 evaluations of f.
template <class Rhs, class Vector, class Time>
void cash_karp_step(const Rhs& f, const Time& t, const Vector& y, const Vector& dydt, const Time& h, Vector& y_out,
                    Vector& err) {
  using namespace cash_karp_tableau;
  const Vector k2 = f(t + a2 * h, Vector(y + h * (b21 * dydt)));
  const Vector k3 = f(t + a3 * h, Vector(y + h * (b31 * dydt + b32 * k2)));
  const Vector k4 = f(t + a4 * h, Vector(y + h * (b41 * dydt + b42 * k2 + b43 * k3)));
  const Vector k5 = f(t + a5 * h, Vector(y + h * (b51 * dydt + b52 * k2 + b53 * k3 + b54 * k4)));
  const Vector k6 = f(t + a6 * h, Vector(y + h * (b61 * dydt + b62 * k2 + b63 * k3 + b64 * k4 + b65 * k5)));
  y_out = y + h * (c1 * dydt + c3 * k3 + c4 * k4 + c6 * k6);
  err = h * (dc1 * dydt + dc3 * k3 + dc4 * k4 + dc5 * k5 + dc6 * k6);
}

// Fixed-step integration over [t0, t1] in `steps` equal Cash-Karp steps (5th order). Works on any
// scalar (ad::Dual gives exact derivatives of the discrete map).
template <class Rhs, class Vector, class Time>
Vector integrate_fixed_steps(const Rhs& f, const Time& t0, const Time& t1, const Vector& y0, int steps) {
  const Time h = (t1 - t0) / double(steps);
  Vector y = y0, y_next = y0, err = y0;
  for (int i = 0; i < steps; ++i) {
    const Time t = t0 + double(i) * h;
    cash_karp_step(f, t, y, Vector(f(t, y)), h, y_next, err);
    y = y_next;
  }
  return y;
}

// Events that never fire.
struct NoEvents {
  template <class Vector>
  Eigen::Matrix<double, 1, 1> operator()(double, const Vector&) const {
    return Eigen::Matrix<double, 1, 1>::Ones();
  }
};

// Observer that ignores every accepted step.
struct NoObserver {
  template <class Vector>
  void operator()(double, const Vector&) const {}
};

// Adaptive integration from (t0, y0) towards t_end (> t0) until an event fires. observe(t, y) is
// called at the start and after every accepted step (and at the located event).
template <class Rhs, class Vector, class Events = NoEvents, class Observer = NoObserver>
IntegrationResult<Vector> integrate(const Rhs& f, double t0, const Vector& y0, double t_end,
                                    const CashKarpOptions& options, const Events& events = {},
                                    const Observer& observe = {}) {
  constexpr double safety = 0.9, grow_exponent = -0.2, shrink_exponent = -0.25, max_growth = 5.0, max_shrink = 0.1;
  IntegrationResult<Vector> result;
  IntegrationStats& stats = result.stats;
  auto rhs = [&](double t, const Vector& y) {
    ++stats.rhs_evaluations;
    return Vector(f(t, y));
  };
  double t = t0;
  Vector y = y0, y_new = y0, err = y0;
  auto g = events(t, y);
  observe(t, y);
  double h = std::min({options.initial_step, options.max_step, t_end - t0});
  auto finish = [&](IntegrationStatus status) {
    result.status = status;
    result.t = t;
    result.y = y;
    return result;
  };
  while (t < t_end) {
    if (stats.accepted_steps + stats.rejected_steps >= options.max_steps) return finish(IntegrationStatus::too_many_steps);
    const Vector dydt = rhs(t, y);
    h = std::min(h, t_end - t);
    double error_norm = 0.0;
    for (;;) {
      cash_karp_step(rhs, t, y, dydt, h, y_new, err);
      error_norm = 0.0;
      for (Eigen::Index i = 0; i < y.size(); ++i) {
        const double scale =
            options.absolute_tolerance + options.relative_tolerance * std::max(std::abs(y[i]), std::abs(y_new[i]));
        error_norm = std::max(error_norm, std::abs(err[i]) / scale);
      }
      if (!std::isfinite(error_norm)) error_norm = 1e10;  // shrink hard on overflow
      if (error_norm <= 1.0) break;
      ++stats.rejected_steps;
      h *= std::max(safety * std::pow(error_norm, shrink_exponent), max_shrink);
      if (h < options.min_step) return finish(IntegrationStatus::step_size_underflow);
    }
    if (!y_new.allFinite()) return finish(IntegrationStatus::non_finite);
    ++stats.accepted_steps;
    const auto g_new = events(t + h, y_new);
    // Earliest sign change g_i > 0 -> g_i <= 0 inside (t, t + h].
    int fired = -1;
    double fired_h = h;
    Vector fired_y = y_new;
    for (Eigen::Index i = 0; i < g_new.size(); ++i) {
      if (!(g[i] > 0.0 && g_new[i] <= 0.0)) continue;
      double lo = 0.0, hi = h, g_lo = g[i], g_hi = g_new[i];
      Vector y_hi = y_new;
      int side = 0;
      while (hi - lo > options.event_time_tolerance * std::max(1.0, std::abs(t))) {
        double trial = hi - g_hi * (hi - lo) / (g_hi - g_lo);
        if (!(trial > lo && trial < hi)) trial = 0.5 * (lo + hi);
        Vector y_trial = y, err_trial = y;
        cash_karp_step(rhs, t, y, dydt, trial, y_trial, err_trial);
        const double g_trial = events(t + trial, y_trial)[i];
        if (g_trial <= 0.0) {
          hi = trial, g_hi = g_trial, y_hi = y_trial;
          if (side == -1) g_lo *= 0.5;  // Illinois: halve the stale end
          side = -1;
        } else {
          lo = trial, g_lo = g_trial;
          if (side == 1) g_hi *= 0.5;
          side = 1;
        }
        if (g_hi == 0.0) break;
      }
      if (fired < 0 || hi < fired_h) fired = int(i), fired_h = hi, fired_y = y_hi;
    }
    if (fired >= 0) {
      t += fired_h;
      y = fired_y;
      observe(t, y);
      result.event_index = fired;
      return finish(IntegrationStatus::event);
    }
    t += h;
    y = y_new;
    g = g_new;
    observe(t, y);
    h = error_norm > 1.89e-4 ? safety * h * std::pow(error_norm, grow_exponent) : max_growth * h;
    h = std::min(h, options.max_step);
  }
  return finish(IntegrationStatus::reached_end);
}

}  // namespace cyclopt::ode
