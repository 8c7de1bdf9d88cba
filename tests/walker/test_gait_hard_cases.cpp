// Hard cases of the periodic-gait evaluation (issue acceptance 5): nearly polygonal feet
// (k = 1e-8 everywhere), the lowest and highest speeds, gaits without a real solution (zeta <= 0,
// eq. 5.87), Floquet multipliers near 1 (eq. 5.85 singular) and degenerate impacts. Every
// evaluation is either real with finite outputs and derivatives, or flagged with a reason.
#include "reference_gaits.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <optional>
#include <set>

namespace cyclopt::walker {
namespace {

// The foot with every regularisation k set to 1e-8, except those named in `keep`.
foot::FootSpec with_sharp_corners(foot::FootSpec s, const std::set<std::string>& keep = {}) {
  const auto layout = foot::parameter_layout(s.model);
  for (std::size_t i = 0; i < layout.size(); ++i)
    if (layout[i].name.substr(0, 2) == "k_" && !keep.count(std::string(layout[i].name))) s.parameters(int(i)) = 1e-8;
  return s;
}

// Gait parameters of the template with contact distance d and torso lean, or why it has none.
std::optional<Eigen::VectorXd> template_gait(const WalkerModel<double>& m, double d, double lean, std::string* why = nullptr) {
  GaitShape shape;
  shape.contact_distance = d;
  shape.torso_lean = lean;
  try {
    return gait_parameters(m, shape);
  } catch (const std::invalid_argument& e) {
    if (why) *why = e.what();
    return std::nullopt;
  }
}

void expect_real_with_finite_derivatives(const GaitEvaluator& ev, const Eigen::VectorXd& x, double speed) {
  const GaitEvaluation e = ev.evaluate_with_derivatives(x, GaitOptions{Objective::mechanical, speed, false});
  ASSERT_TRUE(e.gait.real) << e.gait.failure;
  EXPECT_TRUE(testing::all_finite(e.gait));
  EXPECT_TRUE(e.derivatives.objective.allFinite());
  EXPECT_TRUE(e.derivatives.inequalities.allFinite());
  EXPECT_TRUE(e.derivatives.speed_equality.allFinite());
}

// Every corner of the generating polygon sharp (k = 1e-8) except the flat sole H-M.
TEST(GaitHardCases, FeetWithSharpCornersWalk) {
  for (const char* name : {"P1-barefoot-left-HM", "P2-shoes-left-HMT"}) {
    const GaitEvaluator ev(make_walker_model(with_sharp_corners(foot::foot_preset(name).spec, {"k_HM"})));
    StartingGaitOptions o;
    const StartingGait s = starting_gait(ev, o);
    std::printf("%s, corners k = 1e-8: real %d feasible %d, f_mech %.4f (%s)\n", name, s.real, s.feasible,
                s.gait.f_mech, s.message.c_str());
    ASSERT_TRUE(s.real) << s.message;
    EXPECT_TRUE(s.feasible);
    expect_real_with_finite_derivatives(ev, s.x, o.speed);
  }
}

// A sharp sole transition (k_HM = 1e-8) is narrower than any grid spacing of eq. (5.93): the
// quadrature cannot resolve it, and the evaluation must say so rather than return garbage.
TEST(GaitHardCases, FullyPolygonalFeetAreEitherFiniteOrFlagged) {
  for (const char* name : {"P1-barefoot-left-HM", "P2-shoes-left-HMT"}) {
    const GaitEvaluator ev(make_walker_model(with_sharp_corners(foot::foot_preset(name).spec)));
    int real = 0, flagged = 0;
    for (double d = 0.25; d < 0.9; d += 0.05)
      for (double lean : {0.0, 0.1, 0.2, 0.3}) {
        const std::optional<Eigen::VectorXd> x = template_gait(ev.model(), d, lean);
        if (!x) continue;
        const GaitEvaluation e = ev.evaluate_with_derivatives(*x, GaitOptions{});
        if (e.gait.real) {
          ++real;
          EXPECT_TRUE(testing::all_finite(e.gait));
          EXPECT_TRUE(e.derivatives.inequalities.allFinite());
        } else {
          ++flagged;
          EXPECT_FALSE(e.gait.failure.empty());
        }
      }
    std::printf("%s, all k = 1e-8: %d real (finite), %d flagged\n", name, real, flagged);
    EXPECT_GT(real + flagged, 40);
  }
}

TEST(GaitHardCases, LowestAndHighestSpeedsHaveFiniteDerivatives) {
  for (const char* foot : testing::kReferenceFeet)
    for (double v : {0.3, 2.3}) {
      const auto& ref = testing::reference_gait(foot, v);
      ASSERT_TRUE(ref.start.real) << foot << " " << v << ": " << ref.start.message;
      expect_real_with_finite_derivatives(*ref.evaluator, ref.start.x, v);
    }
}

TEST(GaitHardCases, NoRealSolutionIsFlaggedWithWhereItFails) {
  const GaitEvaluator ev(testing::reference_model("point"));
  GaitShape shape;
  shape.contact_distance = 0.45;
  shape.torso_lean = -0.1;  // leaning back: the gait falls back before the step ends
  const Eigen::VectorXd x = gait_parameters(ev.model(), shape);
  const PeriodicGait<double> g = ev.evaluate(x, GaitOptions{});
  std::printf("flagged: %s\n", g.failure.c_str());
  EXPECT_FALSE(g.real);
  EXPECT_NE(g.failure.find("zeta <= 0"), std::string::npos) << g.failure;
  EXPECT_NE(g.failure.find("5.87"), std::string::npos) << g.failure;
  EXPECT_GE(g.failure_point, 0);
  const GaitEvaluation e = ev.evaluate_with_derivatives(x, GaitOptions{});
  EXPECT_FALSE(e.has_derivatives);
}

// Bisection on the segment between a gait with Lambda < 1 and one with Lambda > 1 (P1 foot at
// 2.3 and 1.3 m/s) towards Lambda = 1, where zeta+ = Lambda I / (1 - Lambda) diverges.
TEST(GaitHardCases, FloquetMultiplierNearOneNeverHidesANan) {
  const auto& slow = testing::reference_gait("P1-barefoot-left-HM", 1.3);
  const auto& fast = testing::reference_gait("P1-barefoot-left-HM", 2.3);
  const GaitEvaluator& ev = *slow.evaluator;
  auto at = [&](double t) { return ev.evaluate(((1.0 - t) * slow.start.x + t * fast.start.x).eval(), GaitOptions{}); };
  double lo = 0.0, hi = 1.0;
  const double s_lo = at(lo).floquet - 1.0, s_hi = at(hi).floquet - 1.0;
  ASSERT_LT(s_lo * s_hi, 0.0) << "reference gaits no longer bracket Lambda = 1";
  int real = 0, flagged = 0;
  double closest = 1.0;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    const PeriodicGait<double> g = at(mid);
    if (!g.real) {
      ++flagged;
      EXPECT_FALSE(g.failure.empty());
      hi = mid;  // move towards the real end
      continue;
    }
    ++real;
    EXPECT_TRUE(testing::all_finite(g)) << "Lambda " << g.floquet;
    closest = std::min(closest, std::abs(g.floquet - 1.0));
    ((g.floquet - 1.0) * s_lo > 0.0 ? lo : hi) = mid;
  }
  std::printf("Lambda -> 1: %d real evaluations (closest |Lambda - 1| = %.2e), %d flagged\n", real, closest, flagged);
  EXPECT_GT(real + flagged, 50);
}

TEST(GaitHardCases, DegenerateImpactPosturesAreFlaggedNotNan) {
  std::set<std::string> reasons;
  int real = 0;
  for (const char* foot : testing::kReferenceFeet) {
    const GaitEvaluator ev(testing::reference_model(foot));
    for (double d = 0.05; d <= 1.4; d += 0.05)
      for (double lean : {-0.3, 0.0, 0.3}) {
        std::string why;
        const std::optional<Eigen::VectorXd> x = template_gait(ev.model(), d, lean, &why);
        if (!x) {
          reasons.insert("template: " + why);
          continue;
        }
        const PeriodicGait<double> g = ev.evaluate(*x, GaitOptions{});
        if (g.real) {
          ++real;
          EXPECT_TRUE(testing::all_finite(g)) << foot << " d " << d;
        } else {
          EXPECT_FALSE(g.failure.empty());
          reasons.insert(g.failure.substr(0, g.failure.find(" at ")));
        }
      }
  }
  std::printf("%d real gaits; failure kinds seen:\n", real);
  for (const std::string& r : reasons) std::printf("  %s\n", r.c_str());
  EXPECT_GE(reasons.size(), 3u);
  EXPECT_GT(real, 0);
}

}  // namespace
}  // namespace cyclopt::walker
