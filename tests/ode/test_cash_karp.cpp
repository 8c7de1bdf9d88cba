// Cash-Karp integration against ODEs with known solutions: 5th-order convergence of the fixed-step
// scheme, tolerance-proportional error of the adaptive one, and event location.
#include "cyclopt/ode/cash_karp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace cyclopt::ode {
namespace {

using Vec2 = Eigen::Vector2d;

// Harmonic oscillator y'' = -y: y = (cos t, -sin t).
Vec2 oscillator(double, const Vec2& y) { return Vec2(y[1], -y[0]); }

TEST(CashKarp, FixedStepsConvergeWithFifthOrder) {
  const double T = 2.0;
  const Vec2 exact(std::cos(T), -std::sin(T));
  double previous = 0.0;
  for (int steps : {10, 20, 40, 80}) {
    const Vec2 y = integrate_fixed_steps(oscillator, 0.0, T, Vec2(1.0, 0.0), steps);
    const double error = (y - exact).norm();
    if (previous > 0.0) {
      const double order = std::log2(previous / error);
      std::printf("steps %3d  error %.3e  observed order %.2f\n", steps, error, order);
      EXPECT_GT(order, 4.7);
      EXPECT_LT(order, 6.5);
    }
    previous = error;
  }
}

TEST(CashKarp, AdaptiveErrorFollowsTolerance) {
  // y' = -2 t y^2, y(0) = 1: y = 1 / (1 + t^2).
  using Vec1 = Eigen::Matrix<double, 1, 1>;
  auto f = [](double t, const Vec1& y) { return Vec1(-2.0 * t * y[0] * y[0]); };
  for (double tol : {1e-6, 1e-9, 1e-12}) {
    CashKarpOptions o;
    o.relative_tolerance = tol;
    o.absolute_tolerance = tol;
    const auto r = integrate(f, 0.0, Vec1(1.0), 10.0, o);
    ASSERT_EQ(r.status, IntegrationStatus::reached_end);
    const double error = std::abs(r.y[0] - 1.0 / 101.0);
    std::printf("tol %.0e  error %.3e  steps %d  rejected %d\n", tol, error, r.stats.accepted_steps, r.stats.rejected_steps);
    EXPECT_LT(error, 50.0 * tol);
    EXPECT_DOUBLE_EQ(r.t, 10.0);
  }
}

TEST(CashKarp, LocatesEventsAccurately) {
  // First zero of cos t (event y0 <= 0) at pi/2; the second component must be -1 there.
  CashKarpOptions o;
  o.relative_tolerance = 1e-12;
  o.absolute_tolerance = 1e-14;
  auto events = [](double, const Vec2& y) { return Eigen::Matrix<double, 1, 1>(y[0]); };
  const auto r = integrate(oscillator, 0.0, Vec2(1.0, 0.0), 10.0, o, events);
  ASSERT_EQ(r.status, IntegrationStatus::event);
  EXPECT_EQ(r.event_index, 0);
  EXPECT_NEAR(r.t, M_PI / 2.0, 1e-11);
  EXPECT_NEAR(r.y[1], -1.0, 1e-11);
}

TEST(CashKarp, PicksTheEarliestOfSeveralEvents) {
  CashKarpOptions o;
  o.initial_step = 5.0;  // both events inside the first attempted step
  auto events = [](double t, const Vec2&) { return Eigen::Vector2d(1.0 - t, 0.5 - t); };
  const auto r = integrate(oscillator, 0.0, Vec2(1.0, 0.0), 10.0, o, events);
  ASSERT_EQ(r.status, IntegrationStatus::event);
  EXPECT_EQ(r.event_index, 1);
  EXPECT_NEAR(r.t, 0.5, 1e-12);
}

}  // namespace
}  // namespace cyclopt::ode
