// The walker as an nlp::Problem (gait_problem.hpp): sizes, names, bounds, failures for gaits
// without a real solution, and the Jacobians of z = [x; free model parameters] (with the foot
// convexity rows) against central differences of the problem's own values.
#include "reference_gaits.hpp"

#include "cyclopt/walker/gait_problem.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace cyclopt::walker {
namespace {

TEST(GaitProblem, SizesNamesAndBounds) {
  const auto& ref = testing::reference_gait("P2-shoes-left-HMT");
  GaitProblem problem(ref.evaluator->model(), {Objective::mechanical, 1.3, Quadrature::trapezoid, {"l_HM", "gamma_F", "m_T"}});
  EXPECT_EQ(problem.num_variables(), 30 + 3);
  EXPECT_EQ(problem.num_equalities(), 1);
  const int foot_rows = static_cast<int>(foot::convexity_constraints(foot::FootModel::hmt).b.size()) + 1;
  EXPECT_EQ(problem.num_inequalities(), 10 * 200 + 3 + foot_rows);
  EXPECT_EQ(problem.variable_name(0), "alpha_2[H1]");
  EXPECT_EQ(problem.variable_name(29), "alpha_tilde_M[F2-]");
  EXPECT_EQ(problem.variable_name(30), "l_HM");
  EXPECT_NE(problem.constraint_name(false, 3).find("5.104c"), std::string::npos);
  EXPECT_NE(problem.constraint_name(false, 2003).find("convexity"), std::string::npos);
  const Eigen::VectorXd lo = problem.lower_bounds(), hi = problem.upper_bounds();
  EXPECT_TRUE(std::isinf(lo(0)));
  EXPECT_DOUBLE_EQ(lo(31), 0.0);                    // gamma_F in [0, pi/2] (3.24)
  EXPECT_DOUBLE_EQ(hi(31), std::numbers::pi / 2);
  EXPECT_THROW(GaitProblem(ref.evaluator->model(), {Objective::mechanical, 1.3, Quadrature::trapezoid, {"wingspan"}}),
               std::invalid_argument);
}

TEST(GaitProblem, NoRealSolutionIsAnEvaluationFailure) {
  const WalkerModel<double> m = testing::reference_model("point");
  GaitProblem problem(m, {});
  GaitShape shape;
  shape.contact_distance = 0.45;
  shape.torso_lean = -0.1;
  nlp::Evaluation e;
  const nlp::EvaluationStatus st = problem.evaluate(problem.initial_point(gait_parameters(m, shape)), true, e);
  EXPECT_FALSE(st.ok);
  EXPECT_NE(st.reason.find("5.87"), std::string::npos) << st.reason;
}

TEST(GaitProblem, JacobianWithFreeFootParametersMatchesCentralDifferences) {
  for (const char* foot : {"P1-barefoot-left-HM", "P2-shoes-left-HMT"}) {
    const auto& ref = testing::reference_gait(foot);
    std::vector<std::string> free = {"h_F", "l_HM", "k_HM", "theta_F0", "m_T"};
    if (std::string(foot) == "P2-shoes-left-HMT") free.push_back("gamma_F");
    GaitProblem problem(ref.evaluator->model(), {Objective::squared_torque, 1.3, Quadrature::trapezoid, free});
    const Eigen::VectorXd z = problem.initial_point(ref.start.x);
    nlp::Evaluation e;
    ASSERT_TRUE(problem.evaluate(z, true, e).ok);
    double worst = 0.0;
    for (int j = 0; j < problem.num_variables(); ++j) {
      const double h = 1e-6 * std::max(1.0, std::abs(z(j)));
      Eigen::VectorXd zp = z, zm = z;
      zp(j) += h;
      zm(j) -= h;
      nlp::Evaluation ep, em;
      ASSERT_TRUE(problem.evaluate(zp, false, ep).ok && problem.evaluate(zm, false, em).ok);
      const double scale = 1.0 + e.gradient.cwiseAbs().maxCoeff();
      worst = std::max(worst, std::abs((ep.objective - em.objective) / (2 * h) - e.gradient(j)) / scale);
      worst = std::max(worst, std::abs((ep.equalities(0) - em.equalities(0)) / (2 * h) - e.equality_jacobian(0, j)) /
                                  (1.0 + e.equality_jacobian.cwiseAbs().maxCoeff()));
      const Eigen::VectorXd fd = (ep.inequalities - em.inequalities) / (2 * h);
      worst = std::max(worst, (fd - e.inequality_jacobian.col(j)).cwiseAbs().maxCoeff() /
                                  (1.0 + e.inequality_jacobian.cwiseAbs().maxCoeff()));
    }
    std::printf("%s with %zu free parameters: max scaled difference AD - central differences %.2e\n", foot, free.size(),
                worst);
    EXPECT_LE(worst, 1e-5) << foot;
  }
}

}  // namespace
}  // namespace cyclopt::walker
