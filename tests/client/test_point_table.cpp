// `cyclopt query` of a foot_design job (point_table.hpp): a density's row prints as one line with
// its optima per class, design parameters, m_F, active bounds (10.1), mean f_mech, savings and
// the speeds its sweep reached, the same for the low-speed design and which is the answer, read
// through records::DesignedFootRecord; a foot_comparison's foot is one line with its mean f_mech,
// saving and speeds, and the job's headline states what the best foot per speed saves.
#include "point_table.hpp"
#include "row_table.hpp"

#include "cyclopt/records/foot_comparison_records.hpp"
#include "cyclopt/records/foot_design_records.hpp"
#include "cyclopt/records/gait_records.hpp"
#include "cyclopt/records/sweep_records.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

namespace cyclopt::client {
namespace {

TEST(PointTable, AFootDesignDensityIsOneLine) {
  records::DesignedFootRecord d;
  d.density = 10;
  d.admissible = true;
  d.starts = 20;
  d.kkt_starts = 5;
  d.admissible_optima = 2;
  d.stilt_optima = 1;
  d.under_resolved_optima = 1;
  d.best = 0;
  d.design = {{{"h_F", 0.1}, {"l_HM", 0.4}}, 0.236, 0.103, 1.98e-3, 2.354};
  d.active_bounds = {"l_HM_max - l_HM >= 0", "h_F_max - h_F >= 0"};
  d.speeds = 21;
  d.speeds_reached = 20;
  d.mean_f_mech = 0.02975;
  d.saving_vs_start = 0.203;
  d.saving_vs_point = 0.67;
  d.low_speeds_reached = 21;
  d.low_mean_f_mech = 0.025;
  d.low_saving_vs_start = 0.412;
  d.low_saving_vs_point = 0.8;
  d.answer = "low-speed design";
  const nlohmann::json row = {{"curve", 0}, {"point", 0}, {"parameter", 10.0}, {"status", "ok"}, {"values", d}};
  const auto s = point_summary(row);
  ASSERT_TRUE(s);
  EXPECT_EQ((*s)["optima_a/s/w/n/u"], "2/1/0/0/1");
  EXPECT_EQ((*s)["active_bounds"], "l_HM_max, h_F_max");
  EXPECT_EQ((*s)["speeds"], "20/21");
  EXPECT_EQ((*s)["low_speeds"], "21/21");
  EXPECT_EQ((*s)["answer"], "low-speed design");
  EXPECT_DOUBLE_EQ((*s)["l_HM"].get<double>(), 0.4);
  std::ostringstream out;
  print_rows(out, nlohmann::json::array({row}), RowFormat::table);
  const std::string text = out.str();
  std::printf("%s", text.c_str());
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2);  // header and the density
  EXPECT_NE(text.find("20.3"), std::string::npos) << text;  // saving vs the start foot, %
  EXPECT_NE(text.find("41.2"), std::string::npos) << text;  // the low-speed design's
}

TEST(PointTable, AComparedFootIsOneLineAndTheEnvelopesSavingTheHeadline) {
  records::ComparedFootRecord reference, foot;
  reference.foot = "point";
  reference.reference = true;
  reference.mean_f_mech = 0.045;
  reference.common_speeds = reference.speeds_found = reference.speeds = 7;
  reference.envelope_saving = 0.591;
  reference.envelope_common_speeds = 7;
  foot.foot = "P2-shoes-left-HMT";
  foot.mean_f_mech = 0.0184;
  foot.saving = 0.5911;
  foot.common_speeds = 7;
  foot.speeds_found = 6;
  foot.speeds = 7;
  const nlohmann::json rows = {{{"curve", 3}, {"point", 0}, {"parameter", 1.0}, {"status", "ok"}, {"values", reference}},
                               {{"curve", 3}, {"point", 1}, {"parameter", 2.0}, {"status", "ok"}, {"values", foot}}};
  const auto s = point_summary(rows[1]);
  ASSERT_TRUE(s);
  EXPECT_EQ((*s)["foot"], "P2-shoes-left-HMT");
  EXPECT_DOUBLE_EQ((*s)["saving_%"].get<double>(), 59.11);
  EXPECT_EQ((*s)["speeds_found"], "6/7");
  const auto r = point_summary(rows[0]);
  ASSERT_TRUE(r);
  EXPECT_EQ((*r)["foot"], "point (reference)");
  EXPECT_TRUE((*r)["saving_%"].is_null());  // a reference saves nothing against itself
  EXPECT_EQ(comparison_envelope_line(rows), "the best foot at each speed saves 59.1 % mean f_mech against point over 7 speeds");
  EXPECT_FALSE(comparison_envelope_line(nlohmann::json::array({rows[1]})));  // only the reference carries it
}

// Issue 54: a sweep's table prints every column with its own fixed decimals, and one line of
// legend says what curve 0 is.
TEST(PointTable, ASweepTableHasFixedDecimalsPerColumnAndALegend) {
  records::GaitRecord g;
  g.real = true;
  g.objective = g.f_mech = 0.0125;
  g.f_usq = 0.3;
  g.mean_speed = 1.0;
  g.step_length = 0.4;
  g.step_period = 0.4;
  g.floquet_multiplier = 0.98;
  g.stable = true;
  g.impact_energy_loss = 1.84;
  g.max_inequality = -0.1;
  g.speed_equality = 0;
  g.theta_plus = 3.0;
  g.theta_minus = 3.3;
  records::SweepBestRecord best;
  best.found_by = "multistart at a seed speed at 1 m/s";
  best.closure = "closed";
  nlohmann::json values = best;
  values["gait"] = g;
  nlohmann::json rows = nlohmann::json::array();
  for (int k = 0; k < 2; ++k) {
    g.f_mech = 0.0125 + 0.01 * k;
    values["gait"] = g;
    rows.push_back({{"curve", k}, {"point", 0}, {"parameter", 1.0}, {"status", "converged"}, {"values", values}});
  }
  std::ostringstream out;
  print_rows(out, rows, RowFormat::table);
  const std::string text = out.str();
  std::printf("%s", text.c_str());
  for (const char* cell : {"1.000 ", "0.012500", "0.022500", "0.4000", "150.0", "0.9800", "1.840"})
    EXPECT_NE(text.find(cell), std::string::npos) << cell;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 4);  // header, two points, the legend
  EXPECT_NE(text.find("curve 0: the best point per speed"), std::string::npos);
  std::ostringstream wide;
  print_rows(wide, rows, RowFormat::wide);
  EXPECT_NE(wide.str().find("speed [m/s]"), std::string::npos);
}

}  // namespace
}  // namespace cyclopt::client
