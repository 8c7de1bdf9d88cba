// Foot specifications in JSON: round trip, presets, and rejection of bad input with errors that
// name the field and the admissible range.
#include "cyclopt/foot/convexity_constraints.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot/foot_spec.hpp"
#include "random_feet.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

namespace cyclopt::foot {
namespace {

using nlohmann::json;

json p1_hm() { return to_json(foot_preset("P1-barefoot-left-HM").spec); }

TEST(FootSpec, RoundTripsEveryPreset) {
  for (const FootPreset& p : foot_presets()) {
    const FootSpec back = foot_spec_from_json(to_json(p.spec));
    EXPECT_EQ(back.model, p.spec.model);
    EXPECT_EQ(back.parameters, p.spec.parameters);
    EXPECT_EQ(back.name, p.spec.name);
  }
}

// The error must name the field and the admissible range.
void expect_rejected(const json& j, const std::string& field, const std::string& fragment) {
  try {
    foot_spec_from_json(j);
    ADD_FAILURE() << "accepted: " << j.dump();
  } catch (const SpecError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(FootSpec, RejectsBadInputNamingFieldAndRange) {
  expect_rejected(json::array(), "foot", "JSON object");
  expect_rejected(json{{"h_F", 0.1}}, "foot.model", "required");
  expect_rejected(json{{"model", "XYZ"}}, "foot.model", "\"HMT\"");
  json j = p1_hm();
  j["k_HM"] = 0.0;
  expect_rejected(j, "foot.k_HM", "[1e-12, 1] rad");
  j = p1_hm();
  j["h_F"] = "0.1";
  expect_rejected(j, "foot.h_F", "must be a number in [0, 0.5] m");
  j = p1_hm();
  j["l_HM"] = -0.2;
  expect_rejected(j, "foot.l_HM", "[0.001, 1] m");
  j = p1_hm();
  j.erase("l_HA");
  expect_rejected(j, "foot.l_HA", "required");
  j = p1_hm();
  j["l_MT"] = 0.05;  // a toe length on a foot without toes
  expect_rejected(j, "foot.l_MT", "allowed:");
  j = p1_hm();
  j["l_HA"] = 0.3;  // beyond the sole
  expect_rejected(j, "foot.l_HA", "must not exceed l_HM");
  j = p1_hm();
  j["periodic_terms"] = 2.5;
  expect_rejected(j, "foot.periodic_terms", "[0, 8]");
  j = p1_hm();
  j["density"] = -1;
  expect_rejected(j, "foot.density", "kg/m^2");
  j = p1_hm();
  j["theta_F0"] = 7.0;
  expect_rejected(j, "foot.theta_F0", "rad");
  j = to_json(foot_preset("P2-shoes-left-HMT").spec);
  j["gamma_F"] = 1.6;
  expect_rejected(j, "foot.gamma_F", "[0, 1.5708] rad");
  j["gamma_F"] = 1.5;
  j["l_MT"] = 0.4;
  j["l_HA"] = 0.2;  // steep long toe rising far above the ankle: polygon not convex at A
  expect_rejected(j, "foot.gamma_F", "not convex");
  j = p1_hm();
  j["h_F"] = std::nan("");
  expect_rejected(j, "foot.h_F", "must be a finite number in [0, 0.5] m");
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

namespace cyclopt::foot {
namespace {

// proto/schemas/foot.schema.json states the same fields and ranges as parameter_layout().
TEST(FootSchema, MatchesTheParameterLayout) {
  std::ifstream in(std::string(CYCLOPT_SOURCE_DIR) + "/proto/schemas/foot.schema.json");
  ASSERT_TRUE(in) << "schema file missing";
  const nlohmann::json schema = nlohmann::json::parse(in);
  for (FootModel model : {FootModel::hm, FootModel::hmt}) {
    const nlohmann::json* variant = nullptr;
    for (const auto& v : schema["oneOf"])
      if (v["properties"]["model"]["const"] == to_string(model)) variant = &v;
    ASSERT_NE(variant, nullptr) << to_string(model);
    for (const ParameterInfo& p : parameter_layout(model)) {
      const auto& prop = (*variant)["properties"][std::string(p.name)];
      EXPECT_DOUBLE_EQ(prop["minimum"].get<double>(), p.min) << p.name;
      EXPECT_DOUBLE_EQ(prop["maximum"].get<double>(), p.max) << p.name;
      const auto& req = (*variant)["required"];
      EXPECT_NE(std::find(req.begin(), req.end(), std::string(p.name)), req.end()) << p.name;
    }
    EXPECT_EQ((*variant)["required"].size(), parameter_layout(model).size() + 1);
  }
}

}  // namespace
}  // namespace cyclopt::foot
