// The walker job kind "sensitivity" (service/walker_sensitivity_kind.hpp; issue 15 item 6, seed
// 001 section 10.1) through the server over memq://: its spec refusals name the field, and a real
// small job (point feet, 1 m/s, two parameters, +-10 % in 2 steps) stores the optimum with its KKT
// sensitivities, the continuation's points and a summary per parameter whose KKT derivative the
// continuation's difference quotients confirm (an independent measurement: re-solved optima).
#include "cyclopt/records/sensitivity_records.hpp"
#include "cyclopt/records/walker_point_record.hpp"
#include "cyclopt/service/job_spec.hpp"
#include "memq_server_fixture.hpp"
#include "spec_rejection.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

namespace cyclopt {
namespace {

using testing::rejected_field;

nlohmann::json sensitivity_spec() {
  return {{"scene", "walker"}, {"task", "sensitivity"}, {"foot", "point"}, {"speed", 1.0},
          {"parameters", {"l_O", "m_T"}}, {"relative_range", 0.1}, {"steps", 2}};
}

TEST(SensitivityJobSpec, RefusesBadFieldsNamingThem) {
  EXPECT_EQ(rejected_field(sensitivity_spec()), "accepted");
  nlohmann::json s = sensitivity_spec();
  s["parameters"] = {"l_O", "no_such_parameter"};
  EXPECT_EQ(rejected_field(s), "parameters[1]");
  s["parameters"] = {"r_F"};  // 0 for point feet: a relative change is undefined
  EXPECT_EQ(rejected_field(s), "parameters[0]");
  s["parameters"] = {"m_T", "m_T"};
  EXPECT_EQ(rejected_field(s), "parameters[1]");
  s["parameters"] = nlohmann::json::array();
  EXPECT_EQ(rejected_field(s), "parameters");
  for (const double range : {0.0, 1.0, -0.1, 1.5}) {
    s = sensitivity_spec();
    s["relative_range"] = range;
    EXPECT_EQ(rejected_field(s), "relative_range") << range;
  }
  s = sensitivity_spec();
  s["steps"] = 0;
  EXPECT_EQ(rejected_field(s), "steps");
  s = sensitivity_spec();
  s["multistart"] = {{"starts", 3}};  // not a field of this task
  EXPECT_NE(rejected_field(s), "accepted");
}

using SensitivityJobs = testing::MemqServerTest;

TEST_F(SensitivityJobs, KktDerivativesAgreeWithTheContinuation) {
  const auto started = std::chrono::steady_clock::now();
  const std::vector<nlohmann::json> rows = run_job("sens-1", sensitivity_spec(), -1);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::optional<records::KktSensitivitiesRecord> kkt;
  std::map<int, records::SensitivitySummaryRecord> summaries;
  std::map<int, int> steps;  // per parameter index
  for (const nlohmann::json& r : rows) {
    const int curve = r["curve"].get<int>(), point = r["point"].get<int>();
    if (curve == records::kSensitivityOptimumCurve) kkt = r["values"].get<records::WalkerPointRecord>().sensitivities;
    else if (curve == records::kSensitivitySummaryCurve) summaries[point] = r["values"].get<records::SensitivitySummaryRecord>();
    else ++steps[curve - records::sensitivity_continuation_curve(0)];
  }
  ASSERT_TRUE(kkt) << "the optimum carries its KKT sensitivities";
  ASSERT_FALSE(kkt->unavailable) << *kkt->unavailable;
  std::printf("job %.1f s; multipliers: %s, |grad L| %.1e, %d active, %zu weakly active\n", seconds, kkt->multipliers.c_str(),
              kkt->lagrangian_gradient, kkt->active_constraints, kkt->weakly_active.size());
  EXPECT_LT(kkt->lagrangian_gradient, 1e-8);
  ASSERT_EQ(kkt->parameters.size(), 2u);
  ASSERT_EQ(summaries.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const records::SensitivitySummaryRecord& s = summaries[k];
    const records::ParameterSensitivityRecord& p = kkt->parameters[static_cast<std::size_t>(k)];
    EXPECT_EQ(s.parameter, p.name);
    EXPECT_EQ(s.derivative, p.derivative);
    EXPECT_EQ(steps[k], 5) << s.parameter << ": -10, -5, 0, +5, +10 %";
    const double h = 0.05 * s.value, central = 0.5 * (s.quotient_decrease + s.quotient_increase);
    std::printf("%-4s KKT df/dp %+.6e, quotients %+.6e / %+.6e (central %+.6e, rel diff %.1e); Delta f predicted %+.4e / %+.4e, "
                "continuation %+.4e / %+.4e; kink %d; %s\n",
                s.parameter.c_str(), s.derivative, s.quotient_decrease, s.quotient_increase, central,
                std::abs(central - s.derivative) / std::abs(s.derivative), s.predicted_decrease, s.predicted_increase,
                s.continuation_decrease, s.continuation_increase, s.kink, s.verdict.c_str());
    EXPECT_NEAR(s.reached_decrease, -0.1, 1e-12);
    EXPECT_NEAR(s.reached_increase, 0.1, 1e-12);
    EXPECT_NEAR(s.predicted_increase, s.derivative * s.value * 0.1, 1e-15);
    // The central difference of re-solved optima is off by O(h^2) from df*/dp on a smooth f*; at
    // a second-order kink (point feet: weakly active swing clearance rows) by O(h) f''-jump.
    EXPECT_NEAR(central, s.derivative, 0.01 * std::abs(s.derivative)) << s.parameter << " (h = " << h << ")";
    // Smooth or second-order kink: the one-sided quotients bracket the derivative, and the
    // verdict says so (agrees, or a kink whose quotients still bracket it).
    EXPECT_TRUE(s.verdict == "agrees" || s.verdict.find("still bracket") != std::string::npos) << s.verdict;
    if (!p.kink && s.verdict != "agrees") {
      EXPECT_NE(s.verdict.find("active set at"), std::string::npos) << "an unflagged kink names the active-set change: " << s.verdict;
    }
  }
}

}  // namespace
}  // namespace cyclopt
