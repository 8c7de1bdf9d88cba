// Foot specifications in JSON: round trip of every preset, rejection of bad input with errors that
// name the field and the admissible range, and the schema against the parameter layout.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/io/foot_spec_json.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

namespace cyclopt::io {
namespace {

using namespace foot;
using nlohmann::json;

json p1_hm() { return to_json(foot_preset("P1-barefoot-left-HM").spec); }

TEST(FootSpecJson, RoundTripsEveryPreset) {
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

TEST(FootSpecJson, RejectsBadInputNamingFieldAndRange) {
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

// proto/schemas/foot.schema.json states the same fields and ranges as parameter_layout().
TEST(FootSpecJson, SchemaMatchesTheParameterLayout) {
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
}  // namespace cyclopt::io
