// Figures of a foot_comparison job (plot/foot_comparison_figures.hpp) from a job document in the
// layout foot_comparison_kind.hpp stores (its records, records/foot_comparison_records.hpp): every foot's curve, the reference dashed black, the
// envelope, outlines of the rolling feet only; SVG and PNG are written.
#include "cyclopt/plot/foot_comparison_figures.hpp"
#include "cyclopt/plot/job_report.hpp"
#include "cyclopt/plot/axes.hpp"
#include "cyclopt/plot/legend.hpp"
#include "cyclopt/plot/scene.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/records/foot_comparison_records.hpp"

#include <gtest/gtest.h>

#include <filesystem>

using namespace cyclopt;

namespace {

nlohmann::json row(int curve, int point, double parameter, nlohmann::json values) {
  return {{"curve", curve}, {"point", point}, {"parameter", parameter}, {"status", "ok"}, {"values", std::move(values)}};
}

// A foot's point at one speed.
nlohmann::json speed_values(const std::string& foot, double f_mech) {
  records::ComparedSpeedRecord r;
  r.foot = foot;
  r.f_mech = f_mech;
  return r;
}

nlohmann::json comparison_document() {
  const std::vector<std::string> feet = {"point", "P2-shoes-left-HMT-SG", "P1-shoes-left-HM-SG"};
  const double f[3][2] = {{0.04, 0.05}, {0.015, 0.02}, {0.016, 0.018}};
  nlohmann::json solutions = nlohmann::json::array();
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 2; ++i) solutions.push_back(row(1 + k, i, 1.0 + 0.5 * i, speed_values(feet[k], f[k][i])));
    records::ComparedFootRecord summary;
    summary.foot = feet[k];
    summary.foot_spec = io::to_json(foot::foot_preset(feet[k]).spec);
    summary.reference = k == 0;
    summary.best_fitted = k == 2;
    summary.saving = k == 0 ? 0.0 : 0.6;
    if (k == 0) summary.envelope_saving = 0.62;
    solutions.push_back(row(4, k, 1 + k, summary));
  }
  solutions.push_back(row(0, 0, 1.0, speed_values(feet[1], 0.015)));
  solutions.push_back(row(0, 1, 1.5, speed_values(feet[2], 0.018)));
  return {{"id", 7}, {"scene", "walker"}, {"task", "foot_comparison"}, {"solutions", solutions}};
}

}  // namespace

TEST(FootComparisonFigures, EveryFootTheReferenceAndTheEnvelope) {
  const plot::FootComparisonCurves c = plot::foot_comparison_curves(comparison_document());
  ASSERT_EQ(c.feet.size(), 3u);
  EXPECT_TRUE(c.feet[0].reference);
  EXPECT_EQ(c.feet[1].f_mech, (std::vector<double>{0.015, 0.02}));
  EXPECT_EQ(c.envelope_f_mech, (std::vector<double>{0.015, 0.018}));
  const plot::LineChart chart = plot::foot_comparison_chart(c);
  ASSERT_EQ(chart.series.size(), 4u);  // three feet and the envelope
  EXPECT_TRUE(chart.series[0].dashed);
  EXPECT_EQ(chart.series[0].color->r, 0.0);
  EXPECT_NE(chart.series.back().label.find("envelope"), std::string::npos);
  EXPECT_NE(chart.series[2].label.find("best"), std::string::npos);
  const plot::Scene outlines = plot::foot_outlines_scene(c);
  EXPECT_EQ(outlines.shapes.size(), 2u);  // point feet have no outline
  // Side by side: the second outline lies right of the first.
  double max_first = -1e9, min_second = 1e9;
  for (const auto& p : outlines.shapes[0].points) max_first = std::max(max_first, p[0]);
  for (const auto& p : outlines.shapes[1].points) min_second = std::min(min_second, p[0]);
  EXPECT_LT(max_first, min_second);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "cyclopt_foot_comparison_figures";
  for (const plot::Figure& f : plot::foot_comparison_figures(comparison_document()))
    for (const std::string& path : plot::write_figure(f, dir.string())) EXPECT_GT(std::filesystem::file_size(path), 1000u);
}

TEST(FootComparisonFigures, SeveralSeedsShadeTheEnvelopeUpToTheWorstSeed) {
  nlohmann::json d = comparison_document();
  EXPECT_TRUE(plot::foot_comparison_chart(plot::foot_comparison_curves(d)).bands.empty())
      << "one seed: no band";
  for (nlohmann::json& s : d["solutions"])
    if (s["curve"] == 0) s["values"]["seed_spread"] = s["point"] == 0 ? 0.2 : 0.05;
  const plot::FootComparisonCurves c = plot::foot_comparison_curves(d);
  EXPECT_EQ(c.envelope_seed_spread, (std::vector<double>{0.2, 0.05}));
  const plot::LineChart chart = plot::foot_comparison_chart(c);
  const plot::Series& envelope = chart.series.back();
  ASSERT_EQ(chart.bands.size(), 1u);
  const plot::Band& band = chart.bands[0];
  EXPECT_EQ(band.low, envelope.y);
  ASSERT_EQ(band.high.size(), 2u);
  EXPECT_DOUBLE_EQ(band.high[0], 0.015 * 1.2);
  EXPECT_DOUBLE_EQ(band.high[1], 0.018 * 1.05);
  EXPECT_NE(envelope.label.find("spread over the seeds"), std::string::npos);
  EXPECT_GE(chart.y_range->hi, 0.05) << "the axis holds every curve";
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "cyclopt_foot_comparison_band";
  for (const plot::Figure& f : plot::foot_comparison_figures(d))
    for (const std::string& path : plot::write_figure(f, dir.string())) EXPECT_GT(std::filesystem::file_size(path), 1000u);
}

TEST(FootComparisonFigures, SeventeenCurvesStayApartByColourOrDash) {
  // The default comparison: point feet and the 16 feet of section 9.2. Ten colours repeat, so the
  // feet after the tenth are dashed; no two feet look alike, and none like the reference.
  plot::FootComparisonCurves c;
  for (int k = 0; k < 17; ++k) {
    plot::ComparedFootCurve f;
    f.name = "foot " + std::to_string(k);
    f.reference = k == 0;
    f.speed = {1.0, 1.5};
    f.f_mech = {0.02 + 0.001 * k, 0.03};
    c.feet.push_back(f);
  }
  const plot::LineChart chart = plot::foot_comparison_chart(c);
  ASSERT_EQ(chart.series.size(), 17u);
  for (std::size_t a = 0; a < chart.series.size(); ++a)
    for (std::size_t b = a + 1; b < chart.series.size(); ++b) {
      const plot::Series &sa = chart.series[a], &sb = chart.series[b];
      const bool same_colour = sa.color->r == sb.color->r && sa.color->g == sb.color->g && sa.color->b == sb.color->b;
      EXPECT_FALSE(same_colour && sa.dashed == sb.dashed) << sa.label << " and " << sb.label;
    }
}

TEST(FootComparisonFigures, TheOutlinesOfSixteenFeetLeaveRoomForTheirLegend) {
  // Four columns of feet make a wide, low picture; capped at the page's width it was 373 px high,
  // and the legend of 16 feet and the ankle (17 rows) ran out of the plot area.
  plot::FootComparisonCurves c;
  for (int k = 0; k < 16; ++k) {
    plot::ComparedFootCurve f;
    f.name = "foot " + std::to_string(k);
    f.spec = foot::foot_preset("P2-shoes-left-HMT-SG").spec;
    f.speed = {1.0};
    f.f_mech = {0.02};
    c.feet.push_back(f);
  }
  const plot::Scene outlines = plot::foot_outlines_scene(c);
  const plot::RenderOptions size = plot::fitted_options(outlines, 760, 600, plot::kPageWidth);
  EXPECT_LE(size.width, plot::kPageWidth);
  EXPECT_GE(size.height - plot::kAxesTopTitled - plot::kAxesBottom, plot::legend_height(17));
}

TEST(FootComparisonFigures, RejectsOtherJobs) {
  nlohmann::json d = comparison_document();
  d["task"] = "sweep";
  EXPECT_THROW(plot::foot_comparison_curves(d), std::invalid_argument);
  d = comparison_document();
  d["solutions"] = nlohmann::json::array();
  EXPECT_THROW(plot::foot_comparison_curves(d), std::invalid_argument);
}

// Issue 54 item 4: a foot comparison's report has the walker reports' provenance box and one
// diagnostics row per stored point, beside its feet-and-savings table and figures.
TEST(FootComparisonFigures, ItsReportHasProvenanceDiagnosticsAndSavings) {
  nlohmann::json doc = comparison_document();
  doc["program_version"] = "abc1234";
  doc["isa_level"] = "x86-64-v2";
  doc["spec"] = {{"scene", "walker"}, {"task", "foot_comparison"}, {"speeds", "1.0:0.5:1.5"}};
  const plot::Report report = plot::job_report(doc);
  ASSERT_GE(report.sections.size(), 4u);
  EXPECT_EQ(report.sections[0].heading, "Provenance");
  EXPECT_TRUE(report.sections[0].boxed);
  const plot::ReportSection& diagnostics = report.sections[2];
  EXPECT_EQ(diagnostics.heading, "Solver diagnostics per stored point");
  ASSERT_EQ(diagnostics.tables.size(), 1u);
  EXPECT_EQ(diagnostics.tables[0].rows.size(), doc["solutions"].size());
  const std::string html = plot::to_html(report);
  for (const char* text : {"<td>program</td><td>abc1234</td>", "x86-64-v2", "Feet and savings", "<td>60.0</td>",
                           "P1-shoes-left-HM-SG"})
    EXPECT_NE(html.find(text), std::string::npos) << text;
}
