// Foot specifications built in code: validation naming the field and the admissible range, the
// preset names, and the convexity conditions. Their JSON form: tests/io/test_foot_spec_json.cpp.
#include "cyclopt/foot/convexity_constraints.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot/foot_spec.hpp"
#include "random_feet.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cyclopt::foot {
namespace {

// A typed field out of its range is rejected without any JSON: field and range in the error.
TEST(FootSpec, ValidateNamesFieldAndRange) {
  FootSpec s = foot_preset("P1-barefoot-left-HM").spec;
  EXPECT_NO_THROW(validate(s));
  s.parameters[hm::k_HM] = 2.0;
  try {
    validate(s, "reference");
    ADD_FAILURE() << "accepted k_HM = 2";
  } catch (const SpecError& e) {
    EXPECT_EQ(e.field(), "reference.k_HM") << e.what();
    EXPECT_NE(std::string(e.what()).find("[1e-12, 1] rad, got 2"), std::string::npos) << e.what();
  }
  s = foot_preset("P1-barefoot-left-HM").spec;
  s.periodic_terms = kMaxPeriodicTerms + 1;
  EXPECT_THROW(validate(s), SpecError);
}

TEST(FootSpec, UnknownPresetListsKnownOnes) {
  try {
    foot_preset("P9");
    ADD_FAILURE();
  } catch (const SpecError& e) {
    EXPECT_NE(std::string(e.what()).find("P2-shoes-left-HMT"), std::string::npos);
  }
}

// The linear conditions (3.21/3.24) hold for every admissible random foot and fail for
// parameters that violate the documented ranges.
TEST(ConvexityConstraints, HoldForAdmissibleFeet) {
  testing::RandomFeet rnd(3);
  for (int draw = 0; draw < 1000; ++draw) {
    const FootSpec s = rnd.any();
    const LinearInequalities li = convexity_constraints(s.model);
    ASSERT_EQ(li.A.cols(), s.parameters.size());
    ASSERT_EQ(static_cast<std::size_t>(li.A.rows()), li.names.size());
    const Eigen::VectorXd slack = li.A * s.parameters + li.b;
    EXPECT_GE(slack.minCoeff(), 0.0);
  }
  FootSpec bad = foot_preset("P2-shoes-left-HMT").spec;
  bad.parameters[hmt::gamma_F] = 2.0;  // beyond pi/2
  const LinearInequalities li = convexity_constraints(FootModel::hmt);
  EXPECT_LT((li.A * bad.parameters + li.b).minCoeff(), 0.0);
  EXPECT_EQ(li.A.rows(), 11);                              // eq. (3.24) has 11 rows
  EXPECT_EQ(convexity_constraints(FootModel::hm).A.rows(), 7);  // eq. (3.21) has 7 rows
}

}  // namespace
}  // namespace cyclopt::foot
