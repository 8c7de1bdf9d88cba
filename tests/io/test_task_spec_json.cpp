// Task specifications in JSON (seed 000, ch. 5 tasks): defaults, round trip, and rejection of bad
// input with errors naming the field and the admissible range.
#include "cyclopt/io/task_spec_json.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <functional>

namespace cyclopt::io {
namespace {

using namespace giant_swing;
using nlohmann::json;

TEST(TaskSpecJson, ChapterFiveDefaults) {
  EXPECT_NEAR(task_spec_from_json(json{{"task", "accelerating"}}).initial_rate * kDegPerRad, 20.0, 1e-12);
  EXPECT_NEAR(task_spec_from_json(json{{"task", "decelerating"}}).initial_rate * kDegPerRad, 80.0, 1e-12);
  EXPECT_EQ(task_spec_from_json(json{{"task", "periodic_sequence"}}).rounds, 10);
  const TaskSpec single = task_spec_from_json(json{{"task", "single_swing"}});
  EXPECT_NEAR(single.omega * kDegPerRad, 40.0, 1e-12);
  EXPECT_EQ(single.weights.phi_rate, 100.0);
  EXPECT_EQ(single.weights.alpha, 10.0);
  EXPECT_EQ(single.weights.alpha_rate, 1.0);
}

TEST(TaskSpecJson, RoundTrips) {
  const json in = {{"task", "periodic_sequence"},
                   {"rounds", 6},
                   {"weights", {{"jerk", 0.01}}},
                   {"alpha_ddot_max_deg_s2", 2000},
                   {"optimiser", {{"start_vector", {1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0}}, {"max_support_points", 32}}}};
  const TaskSpec a = task_spec_from_json(in);
  const TaskSpec b = task_spec_from_json(to_json(a));
  EXPECT_EQ(to_json(a), to_json(b));
  EXPECT_EQ(b.rounds, 6);
  EXPECT_EQ(b.optimiser.support_points, 8);
  EXPECT_NEAR(b.ranges.alpha_acceleration_max * kDegPerRad, 2000.0, 1e-9);
}

void expect_rejected(const json& j, const std::string& field, const std::string& fragment) {
  try {
    task_spec_from_json(j);
    ADD_FAILURE() << "accepted: " << j.dump();
  } catch (const SpecError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(TaskSpecJson, RejectsBadInputNamingTheField) {
  expect_rejected(json{{"omega_deg_s", 40}}, "task.task", "single_swing");
  expect_rejected(json{{"task", "triple_salto"}}, "task.task", "decelerating");
  expect_rejected(json{{"task", "single_swing"}, {"omega_deg_s", -3}}, "task.omega_deg_s", "[1, 360] deg/s");
  expect_rejected(json{{"task", "single_swing"}, {"rounds", 3}}, "task.rounds", "must be 1");
  expect_rejected(json{{"task", "periodic_sequence"}, {"rounds", 99}}, "task.rounds", "[1, 50]");
  expect_rejected(json{{"task", "single_swing"}, {"weights", {{"jerk", -1}}}}, "task.weights.jerk", "[0, 1e+06]");
  expect_rejected(json{{"task", "single_swing"}, {"weights", {{"jerky", 1}}}}, "task.weights.jerky", "allowed");
  expect_rejected(json{{"task", "single_swing"}, {"alpha_max_deg", 200}}, "task.alpha_max_deg", "[0, 180] deg");
  expect_rejected(json{{"task", "single_swing"}, {"optimiser", {{"support_points", 12}}}},
                  "task.optimiser.support_points", "power of two");
  expect_rejected(json{{"task", "single_swing"}, {"optimiser", {{"start_vector", {1, 2, 3}}}}},
                  "task.optimiser.start_vector", "4, 8, 16, 32 or 64");
  expect_rejected(json{{"task", "single_swing"}, {"optimiser", {{"initial_step", 1}, {"min_step", 2}}}},
                  "task.optimiser.min_step", "initial_step");
  expect_rejected(json{{"task", "single_swing"}, {"speed", 1}}, "task.speed", "allowed");
  expect_rejected(json::array(), "task", "JSON object");
}

// proto/schemas/giant_swing_task.schema.json states the same fields and ranges as the parser.
TEST(TaskSpecJson, SchemaMatchesTheParser) {
  std::ifstream in(std::string(CYCLOPT_SOURCE_DIR) + "/proto/schemas/giant_swing_task.schema.json");
  ASSERT_TRUE(in) << "schema file missing";
  const json schema = json::parse(in);
  auto check_numbers = [](const json& properties, const std::function<json(const std::string&, const json&)>& wrap,
                          const std::string& path) {
    for (const auto& [key, p] : properties.items()) {
      if (!p.contains("minimum")) continue;
      const bool integer = p["type"] == "integer";
      EXPECT_NO_THROW(task_spec_from_json(wrap(key, p["minimum"]))) << key;
      EXPECT_NO_THROW(task_spec_from_json(wrap(key, p["maximum"]))) << key;
      const double hi = p["maximum"].get<double>();
      const json above = integer ? json(p["maximum"].get<long long>() + 1) : json(hi * (1 + 1e-9) + 1e-12);
      try {
        task_spec_from_json(wrap(key, above));
        ADD_FAILURE() << key << " accepted above its maximum";
      } catch (const SpecError& e) {
        EXPECT_EQ(e.field(), path + key) << e.what();
      }
    }
  };
  // "rounds" > 1 needs a periodic sequence; min_step <= initial_step is a cross-field rule.
  check_numbers(schema["properties"], [](const std::string& k, const json& v) {
    return json{{"task", "periodic_sequence"}, {k, v}};
  }, "task.");
  check_numbers(schema["properties"]["weights"]["properties"], [](const std::string& k, const json& v) {
    return json{{"task", "single_swing"}, {"weights", {{k, v}}}};
  }, "task.weights.");
  check_numbers(schema["properties"]["optimiser"]["properties"], [](const std::string& k, const json& v) {
    json o = {{k, v}};
    if (k == "min_step") o["initial_step"] = 1e4;
    if (k == "initial_step") o["min_step"] = 1e-9;
    return json{{"task", "single_swing"}, {"optimiser", o}};
  }, "task.optimiser.");
  for (const auto& [key, p] : schema["properties"].items())
    EXPECT_TRUE(to_json(default_task(TaskKind::single_swing)).contains(key) || key == "alpha_ddot_max_deg_s2" ||
                key == "name")
        << key << " in the schema but not written by to_json";
}

}  // namespace
}  // namespace cyclopt::io
