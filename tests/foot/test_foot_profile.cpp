// The rolling-contact function F and its derivatives (seed 001, ch. 2-3, appendix A), checked
// by independent means: complex-step differentiation, the polygon's exact rolling geometry,
// and the rolling condition dx_C/dtheta = R (eq. 2.32).
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot/foot_profile.hpp"
#include "cyclopt/foot/rolling_kinematics.hpp"
#include "random_feet.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <complex>
#include <vector>

namespace cyclopt::foot {
namespace {

using cplx = std::complex<double>;
using testing::RandomFeet;
using testing::with_all_k;

FootProfile<double> profile_of(const FootSpec& s) { return make_profile(s.model, s.parameters, s.periodic_terms); }

// Angles in the admissible range: a uniform grid plus points within a few k of every
// transition, where the derivatives are largest.
std::vector<double> test_angles(const FootProfile<double>& p, int uniform, int per_transition) {
  std::vector<double> th;
  for (int i = 0; i < uniform; ++i) th.push_back(p.theta_min + (p.theta_max - p.theta_min) * i / (uniform - 1));
  for (int i = 0; i < p.transition_count; ++i)
    for (int j = 0; j < per_transition; ++j) {
      const double u = -8.0 + 16.0 * j / (per_transition - 1);
      const double t = p.transitions[i].angle + u * p.transitions[i].k;
      if (t >= p.theta_min && t <= p.theta_max) th.push_back(t);
    }
  return th;
}

// Error of `got` against `ref`, relative where |ref| >= 1 (SI units), absolute below.
double mixed_error(double got, double ref) { return std::abs(got - ref) / std::max(std::abs(ref), 1.0); }

struct DerivativeErrors {
  double d1 = 0, d2 = 0, d3 = 0;
  int angles = 0;
};

// Complex step: f'(x) = Im f(x + i h) / h without cancellation, applied to F (-> F'),
// to the analytic F' (-> F'') and to the analytic F'' (-> F''').
DerivativeErrors complex_step_errors(const FootProfile<double>& p, const std::vector<double>& angles) {
  const double h = 1e-30;
  DerivativeErrors e;
  for (double th : angles) {
    const RollingContact<double> c = rolling_contact(p, th);
    const RollingContact<cplx> cs = rolling_contact(p, cplx(th, h));
    e.d1 = std::max(e.d1, mixed_error(c.dF, cs.F.imag() / h));
    e.d2 = std::max(e.d2, mixed_error(c.ddF, cs.dF.imag() / h));
    e.d3 = std::max(e.d3, mixed_error(c.dddF, cs.ddF.imag() / h));
    ++e.angles;
  }
  return e;
}

// Acceptance 1: analytic F', F'', F''' against complex step at >= 1,000 angles per model.
TEST(FootProfile, AnalyticDerivativesMatchComplexStep) {
  std::vector<FootSpec> feet = {foot_preset("P1-barefoot-left-HM").spec, foot_preset("P2-shoes-left-HMT").spec,
                                with_all_k(foot_preset("P1-barefoot-left-HM").spec, 1e-8),
                                with_all_k(foot_preset("P2-shoes-left-HMT").spec, 1e-8),
                                with_all_k(foot_preset("P2-shoes-left-HMT").spec, 0.5)};
  FootSpec periodic = with_all_k(foot_preset("P2-shoes-left-HMT").spec, 0.5);
  periodic.periodic_terms = 3;  // eq. (3.18)
  feet.push_back(periodic);
  RandomFeet rnd(11);
  for (int i = 0; i < 10; ++i) feet.push_back(rnd.any());

  DerivativeErrors worst;
  for (const FootSpec& s : feet) {
    const FootProfile<double> p = profile_of(s);
    const DerivativeErrors e = complex_step_errors(p, test_angles(p, 1000, 60));
    EXPECT_GE(e.angles, 1000);
    EXPECT_LE(e.d1, 1e-8) << s.name;
    EXPECT_LE(e.d2, 1e-8) << s.name;
    EXPECT_LE(e.d3, 1e-8) << s.name;
    worst.d1 = std::max(worst.d1, e.d1);
    worst.d2 = std::max(worst.d2, e.d2);
    worst.d3 = std::max(worst.d3, e.d3);
  }
  RecordProperty("max_error_dF", std::to_string(worst.d1));
  RecordProperty("max_error_ddF", std::to_string(worst.d2));
  RecordProperty("max_error_dddF", std::to_string(worst.d3));
  std::printf("complex-step check over %zu feet: max mixed error F' %.2e, F'' %.2e, F''' %.2e\n", feet.size(),
              worst.d1, worst.d2, worst.d3);
}

// Acceptance 2 (part): the sign-determining bracket of eq. (A.1) is positive on a dense grid far
// beyond the admissible ranges, k from 1e-10 to 3 (past the critical 2.88 of eq. A.13a).
TEST(FootProfile, ConvexityBracketPositiveEverywhere) {
  double min_bracket = 1e300;
  for (int ik = 0; ik <= 200; ++ik) {
    const double k = std::pow(10.0, -10.0 + 10.477 * ik / 200.0);
    for (int ia = -4000; ia <= 4000; ++ia) {
      const double a = 2.0 * std::numbers::pi * ia / 2000.0;  // [-4 pi, 4 pi]
      const double b = detail::convexity_bracket(a, k, std::tanh(a / k));
      min_bracket = std::min(min_bracket, b);
      ASSERT_GT(b, 0.0) << "a=" << a << " k=" << k;
    }
  }
  std::printf("min of the (A.1) bracket on the grid: %.3e\n", min_bracket);
}

// Acceptance 2: random admissible feet (>= 10,000 draws) have R > 0 on the admissible range,
// wherever R is representable in double; it is never negative or non-finite.
TEST(FootProfile, CurvatureRadiusPositiveForRandomAdmissibleFeet) {
  RandomFeet rnd(2024);
  int checked_positive = 0;
  for (int draw = 0; draw < 10000; ++draw) {
    const FootSpec s = rnd.any();
    const FootProfile<double> p = profile_of(s);
    for (int j = 0; j < 16; ++j) {
      const double th = j < 15 ? rnd.uniform(p.theta_min, p.theta_max) : p.transitions[draw % p.transition_count].angle;
      const double r = curvature_radius(p, th);
      ASSERT_TRUE(std::isfinite(r)) << "draw " << draw;
      ASSERT_GE(r, 0.0) << "draw " << draw;
      // A term is representable when sech^2(a/k) does not underflow (|a/k| < ~350).
      double min_u = 1e300;
      for (int i = 0; i < p.transition_count; ++i)
        min_u = std::min(min_u, std::abs(th - p.transitions[i].angle) / p.transitions[i].k);
      if (min_u < 300.0) {
        ASSERT_GT(r, 0.0) << "draw " << draw << " theta " << th;
        ++checked_positive;
      }
    }
  }
  EXPECT_GT(checked_positive, 50000);
}

// The closed form (3.14) equals F' + F''' (eq. 3.10c) where that sum does not cancel.
TEST(FootProfile, CurvatureRadiusClosedFormEqualsFPrimePlusFTripleprime) {
  RandomFeet rnd(5, 1e-2, 0.5);
  for (int draw = 0; draw < 200; ++draw) {
    const FootProfile<double> p = profile_of(rnd.any());
    for (int j = 0; j < 20; ++j) {
      const double th = rnd.uniform(p.theta_min, p.theta_max);
      const RollingContact<double> c = rolling_contact(p, th);
      const double r = curvature_radius(p, th);
      EXPECT_NEAR(r, c.dF + c.dddF, 1e-10 * std::max({1.0, std::abs(c.dF), std::abs(c.dddF)}));
    }
  }
}

// Acceptance 4: rolling consistency, d x_C / d theta = R (eq. 2.32), x_C = F + F'' (eq. 2.21),
// with the derivative taken by complex step.
TEST(FootProfile, ContactPointAdvancesByTheCurvatureRadius) {
  std::vector<FootSpec> feet = {foot_preset("P1-barefoot-left-HM").spec, foot_preset("P2-shoes-left-HMT").spec,
                                with_all_k(foot_preset("P2-shoes-left-HMT").spec, 1e-8)};
  RandomFeet rnd(77);
  for (int i = 0; i < 10; ++i) feet.push_back(rnd.any());
  const double h = 1e-30;
  double worst = 0.0;
  for (const FootSpec& s : feet) {
    const FootProfile<double> p = profile_of(s);
    for (double th : test_angles(p, 500, 40)) {
      const double dxc = contact_point_on_ground(rolling_contact(p, cplx(th, h))).imag() / h;
      const double r = curvature_radius(p, th);
      worst = std::max(worst, mixed_error(r, dxc));
    }
  }
  EXPECT_LE(worst, 1e-8);
  std::printf("max mixed error of R against d x_C/d theta: %.2e\n", worst);
}

// The generating polygon of a foot, in the foot frame (origin at the ankle A, sole flat).
std::vector<Vector2<double>> polygon_vertices(const FootSpec& s) {
  const auto& p = s.parameters;
  std::vector<Vector2<double>> v = {{0.0, 0.0}, {-p[hm::l_HA], -p[hm::h_F]}, {p[hm::l_HM] - p[hm::l_HA], -p[hm::h_F]}};
  if (s.model == FootModel::hmt)
    v.push_back({p[hmt::l_HM] - p[hmt::l_HA] + p[hmt::l_MT] * std::cos(p[hmt::gamma_F]),
                 -p[hmt::h_F] + p[hmt::l_MT] * std::sin(p[hmt::gamma_F])});
  return v;
}

// Ankle position of the rigid polygon rolled to angle theta (clockwise positive, seed ch. 2):
// the lowest vertex touches the ground, which it reached after rolling over the perimeter from A.
Vector2<double> polygon_ankle(const std::vector<Vector2<double>>& v, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  auto rotated = [&](const Vector2<double>& q) { return Vector2<double>(q.x() * c + q.y() * s, -q.x() * s + q.y() * c); };
  std::size_t low = 0;
  for (std::size_t j = 1; j < v.size(); ++j)
    if (rotated(v[j]).y() < rotated(v[low]).y()) low = j;
  double rolled = 0.0;  // perimeter from A to the contact vertex
  for (std::size_t j = 0; j < low; ++j) rolled += (v[j + 1] - v[j]).norm();
  return Vector2<double>(rolled - rotated(v[low]).x(), -rotated(v[low]).y());
}

// Acceptance 3: as k -> 0 the ankle trajectory (5.10a) converges to the polygon's
// piecewise-circular one (eq. 3.2), at least linearly in k.
TEST(FootProfile, AnkleTrajectoryConvergesToPolygonAsKVanishes) {
  RandomFeet rnd(99);
  std::vector<FootSpec> feet = {foot_preset("P1-barefoot-left-HM").spec, foot_preset("P2-shoes-left-HMT").spec};
  for (int i = 0; i < 6; ++i) feet.push_back(rnd.any());
  for (const FootSpec& base : feet) {
    const auto vertices = polygon_vertices(base);
    double previous = 1e300;
    for (double k : {1e-1, 1e-2, 1e-3, 1e-4, 1e-6, 1e-8}) {
      const FootProfile<double> p = profile_of(with_all_k(base, k));
      double err = 0.0;
      for (int i = 0; i < 2000; ++i) {
        const double th = p.theta_min + (p.theta_max - p.theta_min) * (i + 0.5) / 2000;
        err = std::max(err, (ankle_position(rolling_contact(p, th)) - polygon_ankle(vertices, th)).norm());
      }
      const double scale = base.parameters[hm::l_HM];
      if (&base == &feet.front()) std::printf("P1 HM: max |ankle - polygon ankle| at k = %.0e: %.3e m\n", k, err);
      EXPECT_LE(err, 2.0 * k * scale) << base.name << " k=" << k;
      EXPECT_LT(err, previous) << base.name << " k=" << k;
      previous = err;
    }
    EXPECT_LT(previous, 1e-9);
  }
}

// Acceptance 6: no NaN or Inf anywhere in the admissible range for k in [1e-8, 0.5], including
// exact transition angles and range ends, with and without periodic terms, for double and Dual.
TEST(FootProfile, NoNanOrInfInTheAdmissibleRange) {
  RandomFeet rnd(31337);
  for (int draw = 0; draw < 3000; ++draw) {
    FootSpec s = rnd.any();
    s.periodic_terms = draw % 3;
    const FootProfile<double> p = profile_of(s);
    std::vector<double> angles = {p.theta_min, p.theta_max};
    for (int i = 0; i < p.transition_count; ++i) angles.push_back(p.transitions[i].angle);
    for (int j = 0; j < 8; ++j) angles.push_back(rnd.uniform(p.theta_min, p.theta_max));
    for (double th : angles) {
      const RollingContact<double> c = rolling_contact(p, th);
      ASSERT_TRUE(std::isfinite(c.F) && std::isfinite(c.dF) && std::isfinite(c.ddF) && std::isfinite(c.dddF))
          << "draw " << draw << " theta " << th;
      ASSERT_TRUE(std::isfinite(curvature_radius(p, th)));
      using D = ad::Dual<2>;
      const FootProfile<D> pd = make_profile<D>(s.model, s.parameters.cast<D>().eval(), s.periodic_terms);
      const RollingContact<D> cd = rolling_contact(pd, D::variable(th, 0));
      ASSERT_TRUE(ad::isfinite(cd.F) && ad::isfinite(cd.dF) && ad::isfinite(cd.ddF) && ad::isfinite(cd.dddF));
    }
  }
}

// The point foot: the ankle is the contact point.
TEST(FootProfile, PointFootHasNoGeometry) {
  const FootSpec s = foot_preset("point").spec;
  const FootProfile<double> p = profile_of(s);
  EXPECT_EQ(p.transition_count, 0);
  const RollingContact<double> c = rolling_contact(p, 0.3);
  EXPECT_EQ(c.F, 0.0);
  EXPECT_EQ(contact_point_from_ankle(c).norm(), 0.0);
}

}  // namespace
}  // namespace cyclopt::foot
