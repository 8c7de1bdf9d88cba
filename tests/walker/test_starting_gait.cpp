// Automatic starting gaits (starting_gait.hpp): a real, feasible periodic gait at every speed of
// the seed's range 0.3-2.3 m/s for every reference foot, and a reproducible perturbation sampler.
#include "reference_gaits.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

namespace cyclopt::walker {
namespace {

void expect_feasible_over_the_speed_range(const char* foot) {
  const GaitEvaluator ev(testing::reference_model(foot));
  for (double v : {0.3, 0.8, 1.3, 1.8, 2.3}) {
    StartingGaitOptions o;
    o.speed = v;
    const auto t0 = std::chrono::steady_clock::now();
    const StartingGait s = starting_gait(ev, o);
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%s v = %.1f m/s: real %d feasible %d, c_g %.1e, max c_u %.2e, f_mech %.4f, Lambda %.3f, %d evaluations, "
                "%.2f s (%s)\n", foot, v, s.real, s.feasible, s.speed_error, s.max_violation, s.gait.f_mech,
                s.gait.floquet, s.evaluations, dt, s.message.c_str());
    ASSERT_TRUE(s.real) << foot << " " << v << ": " << s.message;
    EXPECT_TRUE(s.feasible) << foot << " " << v;
    EXPECT_NEAR(s.gait.mean_speed, v, 1e-8);
    EXPECT_TRUE(testing::all_finite(s.gait));
  }
}

TEST(StartingGait, FeasibleOverTheSpeedRangeHM) { expect_feasible_over_the_speed_range("P1-barefoot-left-HM"); }
TEST(StartingGait, FeasibleOverTheSpeedRangeHMT) { expect_feasible_over_the_speed_range("P2-shoes-left-HMT"); }
TEST(StartingGait, FeasibleOverTheSpeedRangePointFeet) { expect_feasible_over_the_speed_range("point"); }

TEST(StartingGait, RejectsASpeedOutsideTheRangeNamingTheField) {
  const GaitEvaluator ev(testing::reference_model("point"));
  StartingGaitOptions o;
  o.speed = -1.0;
  try {
    starting_gait(ev, o);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("speed"), std::string::npos) << e.what();
  }
}

TEST(PerturbationSampler, ReproducibleAndAlwaysReal) {
  const auto& ref = testing::reference_gait("P2-shoes-left-HMT");
  const GaitEvaluator& ev = *ref.evaluator;
  std::mt19937_64 a(42), b(42);
  for (int i = 0; i < 20; ++i) {
    const Eigen::VectorXd xa = perturbed_gait(ev, ref.start.x, 0.05, a), xb = perturbed_gait(ev, ref.start.x, 0.05, b);
    EXPECT_EQ(xa, xb);
    EXPECT_GT((xa - ref.start.x).norm(), 0.0);
    EXPECT_TRUE(ev.evaluate(xa, GaitOptions{}).real);
  }
  std::mt19937_64 c(1);
  EXPECT_THROW(perturbed_gait(ev, ref.start.x, 10.0, c, 50), std::runtime_error);
}

}  // namespace
}  // namespace cyclopt::walker
