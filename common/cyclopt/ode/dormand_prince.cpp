#include "cyclopt/ode/dormand_prince.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace cyclopt::ode {

namespace {

// Butcher tableau of Dormand & Prince (1980), RK5(4)7M.
constexpr std::array<double, 7> c = {0.0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1.0, 1.0};
constexpr double a[7][6] = {
    {},
    {1.0 / 5},
    {3.0 / 40, 9.0 / 40},
    {44.0 / 45, -56.0 / 15, 32.0 / 9},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
    {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84},
};
// 5th-order weights (= last row of a) and the difference to the embedded 4th-order ones.
constexpr std::array<double, 7> b = {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0.0};
constexpr std::array<double, 7> e = {71.0 / 57600, 0.0, -71.0 / 16695, 71.0 / 1920, -17253.0 / 339200, 22.0 / 525, -1.0 / 40};
// Continuous extension (Hairer, Norsett & Wanner, dense output of DOPRI5).
constexpr std::array<double, 7> d = {-12715105075.0 / 11282082432, 0.0, 87487479700.0 / 32700410799,
                                     -10690763975.0 / 1880347072, 701980252875.0 / 199316789632,
                                     -1453857185.0 / 822651844, 69997945.0 / 29380423};

struct Step {
  std::array<Eigen::VectorXd, 7> k;
  Eigen::VectorXd y_new, err;
};

void rk_step(const RightHandSide& f, double t, const Eigen::VectorXd& y, const Eigen::VectorXd& k0, double h, Step& s,
             int& evaluations) {
  s.k[0] = k0;
  Eigen::VectorXd yi(y.size());
  for (int i = 1; i < 7; ++i) {
    yi = y;
    for (int j = 0; j < i; ++j)
      if (a[i][j] != 0.0) yi += h * a[i][j] * s.k[j];
    f(t + c[i] * h, yi, s.k[i]);
    ++evaluations;
    if (i == 6) s.y_new = yi;  // FSAL: stage 7 is evaluated at the 5th-order solution
  }
  s.err = Eigen::VectorXd::Zero(y.size());
  for (int i = 0; i < 7; ++i) s.err += h * e[i] * s.k[i];
}

// y(t + theta h) from the continuous extension of the accepted step.
Eigen::VectorXd dense(const Eigen::VectorXd& y, const Eigen::VectorXd& y_new, const Step& s, double h, double th) {
  const Eigen::VectorXd r1 = y_new - y;
  const Eigen::VectorXd r2 = h * s.k[0] - r1;
  const Eigen::VectorXd r3 = r1 - h * s.k[6] - r2;
  Eigen::VectorXd r4 = Eigen::VectorXd::Zero(y.size());
  for (int i = 0; i < 7; ++i) r4 += h * d[i] * s.k[i];
  const double u = 1.0 - th;
  return y + th * (r1 + u * (r2 + th * (r3 + u * r4)));
}

}  // namespace

IntegrationResult integrate(const RightHandSide& f, double t0, const Eigen::VectorXd& y0, double t_end,
                            const IntegratorOptions& o, const EventFunction& event) {
  IntegrationResult r;
  double t = t0, h = std::min(o.initial_step, t_end - t0);
  Eigen::VectorXd y = y0, k0(y0.size());
  f(t, y, k0);
  ++r.evaluations;
  double g_prev = event ? event(t, y) : 0.0;
  Step s;
  while (r.steps < o.max_steps) {
    if (t >= t_end) {
      r.ok = true;
      r.t = t;
      r.y = y;
      r.message = "reached t_end";
      return r;
    }
    h = std::min({h, o.max_step, t_end - t});
    rk_step(f, t, y, k0, h, s, r.evaluations);
    double err = 0.0;
    for (int i = 0; i < y.size(); ++i) {
      const double sc = o.absolute_tolerance + o.relative_tolerance * std::max(std::abs(y(i)), std::abs(s.y_new(i)));
      err += (s.err(i) / sc) * (s.err(i) / sc);
    }
    err = std::sqrt(err / double(y.size()));
    if (!std::isfinite(err)) {
      r.rejected_steps++;
      h *= 0.2;
      if (h < 1e-15 * std::max(1.0, std::abs(t))) break;
      continue;
    }
    const double factor = std::clamp(0.9 * std::pow(std::max(err, 1e-10), -0.2), 0.2, 5.0);
    if (err > 1.0) {
      ++r.rejected_steps;
      h *= std::max(factor, 0.2);
      continue;
    }
    ++r.steps;
    if (event) {
      const double g_new = event(t + h, s.y_new);
      if (g_prev > 0.0 && g_new <= 0.0) {
        // Illinois iteration on the continuous extension for theta in (0, 1].
        double lo = 0.0, hi = 1.0, glo = g_prev, ghi = g_new;
        int side = 0;
        for (int it = 0; it < 200 && (hi - lo) * h > o.event_tolerance; ++it) {
          double th = (lo * ghi - hi * glo) / (ghi - glo);
          if (!(th > lo && th < hi)) th = 0.5 * (lo + hi);
          const double gt = event(t + th * h, dense(y, s.y_new, s, h, th));
          if (gt > 0.0) {
            lo = th, glo = gt;
            if (side == -1) ghi *= 0.5;
            side = -1;
          } else {
            hi = th, ghi = gt;
            if (side == 1) glo *= 0.5;
            side = 1;
          }
        }
        Step last;
        rk_step(f, t, y, k0, hi * h, last, r.evaluations);
        r.ok = r.event = true;
        r.t = t + hi * h;
        r.y = last.y_new;
        r.message = "event";
        return r;
      }
      g_prev = g_new;
    }
    t += h;
    y = s.y_new;
    k0 = s.k[6];
    h *= factor;
  }
  r.t = t;
  r.y = y;
  r.message = r.steps >= o.max_steps ? "step limit reached" : "step size underflow";
  return r;
}

}  // namespace cyclopt::ode
