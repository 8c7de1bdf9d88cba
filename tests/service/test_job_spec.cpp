// Job-spec validation: value ranges, common fields, the foot_sweep kind; every error names its
// field.
#include "cyclopt/jobs/builtin_job_kinds.hpp"
#include "cyclopt/jobs/foot/foot_kinds.hpp"
#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/service/value_range.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace cyclopt::service {
namespace {

using namespace cyclopt::jobs;

// The field named by the SpecError `f` throws ("" if it does not throw).
template <class F>
std::string failing_field(F&& f) {
  try {
    f();
  } catch (const SpecError& e) {
    return e.field();
  }
  return "";
}

nlohmann::json sweep_spec() {
  return {{"scene", "walker"},
          {"task", "foot_sweep"},
          {"foot", "P2-shoes-left-HMT"},
          {"sweep", {{"parameter", "density"}, {"values", "20:10:60"}}}};
}

TEST(ValueRange, ColonSyntaxIncludesTheEnd) {
  const auto v = parse_value_range("0.3:0.1:2.3", "speeds", 0.0, 5.0);
  ASSERT_EQ(v.size(), 21u);
  for (int i = 0; i <= 20; ++i) {  // each the double of its decimal, as if typed: 0.3 + 0.1 i is not
    char decimal[8];
    std::snprintf(decimal, sizeof decimal, "%.1f", 0.3 + 0.1 * i);
    EXPECT_EQ(v[static_cast<std::size_t>(i)], std::stod(decimal)) << decimal;
  }
  EXPECT_NE(0.3 + 0.1 * 3, 0.6);  // what the grid would hold unrounded
  EXPECT_EQ(parse_value_range("-0.2:0.1:0.2", "values", -1.0, 1.0)[2], 0.0);  // not 2.8e-17
  EXPECT_EQ(parse_value_range(1.5, "speeds", 0.0, 5.0), std::vector<double>{1.5});
  EXPECT_EQ(parse_value_range(nlohmann::json::array({1, 2}), "speeds", 0.0, 5.0), (std::vector<double>{1, 2}));
}

TEST(ValueRange, RejectsBadGrids) {
  for (const nlohmann::json& bad : {nlohmann::json("1:2"), nlohmann::json("a:0.1:2"), nlohmann::json("2:0.1:1"),
                                    nlohmann::json("1:0:2"), nlohmann::json("0:1e-9:1"), nlohmann::json("0:1:9"),
                                    nlohmann::json::array(), nlohmann::json(true)})
    EXPECT_EQ(failing_field([&] { parse_value_range(bad, "speeds", 0.0, 5.0); }), "speeds") << bad.dump();
}

// The message of the SpecError `f` throws ("" if it does not throw).
template <class F>
std::string failing_message(F&& f) {
  try {
    f();
  } catch (const SpecError& e) {
    return e.what();
  }
  return "";
}

TEST(ValueRange, TheLastPointMayRoundAboveHi) {
  // 0.1 + 9999 * 0.1 = 1000.0000000000001: still the grid's end, stored as exactly 1000.
  const auto v = parse_value_range("0.1:0.1:1000", "continuation.values", -1e3, 1e3);
  ASSERT_EQ(v.size(), 10000u);
  EXPECT_EQ(v.back(), 1000.0);
  EXPECT_EQ(parse_value_range("0.6:0.1:1.4", "speeds", 0.1, 3.0).size(), 9u);
  EXPECT_EQ(parse_value_range("0:0.3:1", "speeds", 0.0, 3.0).size(), 4u);  // 1 is not on the grid
}

TEST(ValueRange, HugeGridsReportTheirSizeWithoutOverflow) {
  const std::string m = failing_message([] { parse_value_range("-1e308:1e-300:1e308", "speeds", -1e308, 1e308); });
  EXPECT_NE(m.find("more than 1e308 points"), std::string::npos) << m;
  const std::string m2 = failing_message([] { parse_value_range("0:1e-6:1", "speeds", 0.0, 5.0); });
  EXPECT_NE(m2.find("has 1e+06 points; at most 10000"), std::string::npos) << m2;
}

TEST(JobSpec, NumbersBeyondDoubleNameTheirField) {
  EXPECT_EQ(failing_field([] { parse_job_spec_text(R"({"scene": "walker", "speed": 1e400})"); }), "speed");
  EXPECT_EQ(failing_field([] { parse_job_spec_text(R"({"start": [0.1, [2], -1e999]})"); }), "start[2]");
  EXPECT_EQ(failing_field([] { parse_job_spec_text(R"({"limits": {"max_wall_seconds": 1e400}, "a": 1})"); }),
            "limits.max_wall_seconds");
  EXPECT_EQ(failing_field([] { parse_job_spec_text("1e400"); }), "spec_json");
  const std::string m = failing_message([] { parse_job_spec_text(R"({"speed": 1e400})"); });
  EXPECT_NE(m.find("1e400 is outside the range of a double"), std::string::npos) << m;
}

TEST(JobSpec, AcceptsAFootSweep) {
  const JobKindRegistry kinds = builtin_job_kinds();
  const ValidatedJobSpec v = validate_job_spec(sweep_spec(), kinds);
  EXPECT_EQ(v.task, "foot_sweep");
  EXPECT_EQ(v.kind, kinds.find("foot_sweep"));
}

TEST(JobSpec, ErrorsNameTheField) {
  const JobKindRegistry kinds = builtin_job_kinds();
  auto field_of = [&](const nlohmann::json& spec) { return failing_field([&] { validate_job_spec(spec, kinds); }); };
  auto with = [](const std::string& ptr, const nlohmann::json& value) {
    nlohmann::json s = sweep_spec();
    s[nlohmann::json::json_pointer(ptr)] = value;
    return s;
  };
  EXPECT_EQ(field_of(with("/scene", "robot")), "scene");
  EXPECT_EQ(field_of(with("/scene", "giant_swing")), "scene");
  JobKindRegistry foot_only;  // a server that implements only foot_sweep
  foot_only.add(foot_sweep_kind());
  EXPECT_EQ(failing_field([&] { validate_job_spec(with("/task", "optimise"), foot_only); }), "task");
  EXPECT_EQ(field_of(with("/task", 3)), "task");
  EXPECT_EQ(field_of(with("/colour", "red")), "colour");
  EXPECT_EQ(field_of(with("/limits/max_wall_seconds", -1)), "limits.max_wall_seconds");
  // The message names the range that is admitted: 0 is not (issue 57).
  for (const nlohmann::json& bad : {nlohmann::json(-1), nlohmann::json(0), nlohmann::json(1e6), nlohmann::json("60")}) {
    const std::string m = failing_message([&] { validate_job_spec(with("/limits/max_wall_seconds", bad), kinds); });
    EXPECT_NE(m.find("(0, 604800]"), std::string::npos) << m;
    EXPECT_EQ(m.find("[0,"), std::string::npos) << m;
  }
  EXPECT_EQ(field_of(with("/limits/max_iterations", 1.5)), "limits.max_iterations");
  EXPECT_EQ(field_of(with("/solver/solver", "newton")), "solver.solver");
  EXPECT_EQ(field_of(with("/objective", "speed")), "objective");
  EXPECT_EQ(field_of(with("/foot", "no-such-foot")), "foot");
  EXPECT_EQ(field_of(with("/foot", nlohmann::json{{"model", "HM"}, {"h_F", 0.08}})), "foot.l_HA");
  EXPECT_EQ(field_of(with("/sweep/parameter", "gamma_F_typo")), "sweep.parameter");
  EXPECT_EQ(field_of(with("/sweep/values", "0:10:2000")), "sweep.values");
  EXPECT_EQ(field_of(with("/point_delay_ms", 20000)), "point_delay_ms");
  const nlohmann::json optimise = {{"scene", "walker"}, {"task", "optimise"}, {"foot", "point"}, {"speed", 1.0}};
  auto optimise_with = [&](const nlohmann::json& extra) {
    nlohmann::json o = optimise;
    o.update(extra);
    return o;
  };
  EXPECT_EQ(field_of(optimise_with({{"positive_power_band", -1e-3}})), "positive_power_band");
  EXPECT_EQ(field_of(optimise_with({{"positive_power_band", 5.0}})), "positive_power_band");
  EXPECT_EQ(field_of(optimise_with({{"positive_power_band", 1e-3}, {"quadrature", "corrected_trapezoid"}})),
            "positive_power_band");
  EXPECT_EQ(field_of(optimise_with({{"positive_power_band", 1e-3}})), "");
  // Grid values that make an invalid foot are caught before the job is queued.
  nlohmann::json s = with("/sweep/parameter", "l_HA");
  s["sweep"]["values"] = "0.05:0.1:0.95";
  EXPECT_EQ(field_of(s), "sweep.values[2]");
  EXPECT_EQ(failing_field([] { parse_job_spec_text("{\"scene\": "); }), "spec_json");
  EXPECT_EQ(failing_field([] { parse_job_spec_text("[1, 2]"); }), "spec_json");
  // Deep nesting within the 16 KiB limit neither overflows the stack nor passes.
  EXPECT_EQ(failing_field([] { parse_job_spec_text(std::string(16000, '[')); }), "spec_json");
  EXPECT_EQ(failing_field([] { parse_job_spec_text(std::string(8000, '[') + std::string(8000, ']')); }), "spec_json");
  const std::string deep = "{\"scene\": \"walker\", \"task\": \"foot_sweep\", \"foot\": " + std::string(7000, '[') +
                           std::string(7000, ']') + "}";
  EXPECT_EQ(failing_field([&] { validate_job_spec(parse_job_spec_text(deep), builtin_job_kinds()); }), "foot");
}

// An Ipopt job that names no band gets kIpoptPositivePowerBand (the interior-point method needs the
// kink of max(u q_dot, 0) rounded); the SQP and the corrected rule keep the seed's positive part.
TEST(JobSpec, AnIpoptJobRoundsThePositivePartUnlessTheSpecSaysOtherwise) {
  const auto band = [](const nlohmann::json& extra) {
    nlohmann::json spec = {{"scene", "walker"}, {"task", "optimise"}, {"foot", "point"}, {"speed", 1.3}};
    spec.update(extra);
    return parse_walker_job(spec, parse_common_job_fields(spec), false).problem.positive_power_band;
  };
  const nlohmann::json ipopt = {{"solver", "ipopt"}};
  EXPECT_EQ(band(nlohmann::json::object()), 0.0);
  EXPECT_EQ(band({{"solver", {{"solver", "sqp"}}}}), 0.0);
  EXPECT_EQ(band({{"solver", ipopt}}), kIpoptPositivePowerBand);
  EXPECT_EQ(band({{"solver", ipopt}, {"quadrature", "corrected_trapezoid"}}), 0.0);
  EXPECT_EQ(band({{"solver", ipopt}, {"positive_power_band", 0.0}}), 0.0);
  EXPECT_EQ(band({{"solver", ipopt}, {"positive_power_band", 0.25}}), 0.25);
}

TEST(JobSpec, LimitsAreCappedByTheServer) {
  nlohmann::json s = sweep_spec();
  s["limits"] = {{"max_wall_seconds", 10.0}, {"max_iterations", 1000000}};
  const JobLimits l = effective_limits(validate_job_spec(s, builtin_job_kinds()).common.limits,
                                      {.max_wall_seconds = 60.0, .max_iterations = 500});
  EXPECT_EQ(l.max_wall_seconds, 10.0);
  EXPECT_EQ(l.max_iterations, 500);
}

}  // namespace
}  // namespace cyclopt::service
