// Nelder-Mead (seed 000, ch. 4.1) on Rosenbrock and on the seed's own test function (Fig. 4.2).
#include "cyclopt/nlp/nelder_mead.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace cyclopt::nlp {
namespace {

double rosenbrock(const Eigen::VectorXd& x) {
  double f = 0.0;
  for (Eigen::Index i = 0; i + 1 < x.size(); ++i)
    f += 100.0 * std::pow(x[i + 1] - x[i] * x[i], 2) + std::pow(1.0 - x[i], 2);
  return f;
}

TEST(NelderMead, MinimisesRosenbrockInTwoDimensions) {
  NelderMeadOptions o;
  o.initial_step = 0.5;
  o.f_tolerance = 1e-14;
  const auto s = nelder_mead(rosenbrock, Eigen::Vector2d(-1.2, 1.0), o);
  std::printf("2-d Rosenbrock: x = (%.8f, %.8f), f = %.3e, %d evaluations\n", s.x[0], s.x[1], s.f, s.evaluations);
  EXPECT_EQ(s.termination, NelderMeadTermination::converged);
  EXPECT_NEAR(s.x[0], 1.0, 1e-5);
  EXPECT_NEAR(s.x[1], 1.0, 1e-5);
  EXPECT_LT(s.f, 1e-10);
}

TEST(NelderMead, RestartsReachRosenbrockMinimumInFourDimensions) {
  NelderMeadOptions o;
  o.initial_step = 0.5;
  o.f_tolerance = 1e-15;
  Eigen::VectorXd x = Eigen::VectorXd::Constant(4, -0.5);
  int evaluations = 0;
  for (int restart = 0; restart < 10; ++restart) {  // the restarts of the seed's loop (ch. 4.3)
    const auto s = nelder_mead(rosenbrock, x, o);
    evaluations += s.evaluations;
    x = s.x;
  }
  std::printf("4-d Rosenbrock: f = %.3e after %d evaluations\n", rosenbrock(x), evaluations);
  EXPECT_NEAR((x - Eigen::VectorXd::Ones(4)).norm(), 0.0, 1e-5);
}

TEST(NelderMead, SeedTestFunctionAndBudget) {
  // Fig. 4.2: f = (x + 2)^2 + (y + 3)^2 from the simplex (0,0), (1,0), (0,1).
  auto f = [](const Eigen::VectorXd& x) { return std::pow(x[0] + 2.0, 2) + std::pow(x[1] + 3.0, 2); };
  NelderMeadOptions o;
  o.initial_step = 1.0;
  o.f_tolerance = 1e-12;
  const auto s = nelder_mead(f, Eigen::Vector2d(0.0, 0.0), o);
  EXPECT_NEAR(s.x[0], -2.0, 1e-5);
  EXPECT_NEAR(s.x[1], -3.0, 1e-5);
  o.max_evaluations = 20;
  const auto capped = nelder_mead(f, Eigen::Vector2d(0.0, 0.0), o);
  EXPECT_EQ(capped.termination, NelderMeadTermination::max_evaluations);
  EXPECT_LE(capped.evaluations, 20 + 3);
}

}  // namespace
}  // namespace cyclopt::nlp
