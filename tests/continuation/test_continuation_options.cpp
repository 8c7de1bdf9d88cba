// Options, parameter grids and the jump test of the continuation (seed 001, Table 7.1).
#include "cyclopt/continuation/continuation_solver.hpp"
#include "cyclopt/continuation/curve_jump.hpp"

#include <gtest/gtest.h>

using namespace cyclopt::continuation;

TEST(ContinuationOptions, DefaultsAreTable7_1AndValidate) {
  const ContinuationOptions o;
  EXPECT_DOUBLE_EQ(o.tau, 0.8);
  EXPECT_DOUBLE_EQ(o.eta, 1e-4);
  EXPECT_DOUBLE_EQ(o.min_trust_region, 0.002);
  EXPECT_NO_THROW(validate(o));
}

TEST(ContinuationOptions, ErrorsNameTheField) {
  ContinuationOptions o;
  o.tau = 1.0;
  try {
    validate(o);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("tau"), std::string::npos);
  }
  EXPECT_THROW(parse_predictor("tangent"), std::invalid_argument);
  EXPECT_EQ(parse_predictor("qp"), Predictor::qp);
}

TEST(ContinuationOptions, ParametersMustBeMonotone) {
  const ParametricProblem none{"p", {}};
  EXPECT_THROW(continue_solution(none, Eigen::VectorXd::Zero(1), {1.0}, {}), std::invalid_argument);
  EXPECT_THROW(continue_solution(none, Eigen::VectorXd::Zero(1), {1.0, 1.2, 1.1}, {}), std::invalid_argument);
}

TEST(CurveJump, SecantFarAboveThePreviousOneIsAJump) {
  const ContinuationOptions o;
  const Eigen::VectorXd a = Eigen::VectorXd::Ones(4);
  Eigen::VectorXd near = a, far = a;
  near[0] += 0.01;
  far[0] += 1.0;
  EXPECT_FALSE(test_jump(a, near, 0.1, 0.1, o).jump);
  EXPECT_TRUE(test_jump(a, far, 0.1, 0.1, o).jump);
  EXPECT_FALSE(test_jump(a, far, 0.1, 20.0, o).jump);  // the curve itself moves that fast
  EXPECT_TRUE(test_jump(a, far, 0.1, std::nullopt, o).jump);
  EXPECT_FALSE(test_jump(a, near, 0.1, std::nullopt, o).jump);
}
