// Plots: files are valid PNG/SVG/PDF of the requested size, and the curves, outlines and markers
// that were asked for are really drawn (pixels of their colours exist).
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/plot/axes.hpp"
#include "cyclopt/plot/foot_figures.hpp"
#include "cyclopt/plot/html_report.hpp"
#include "cyclopt/plot/line_chart.hpp"
#include "cyclopt/plot/rich_text.hpp"
#include "cyclopt/plot/scene.hpp"
#include "png_inspection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace cyclopt::plot {
namespace {

namespace fs = std::filesystem;

fs::path out_dir() { return testing::output_dir("cyclopt_test_plot"); }

std::string head_of(const fs::path& p, std::size_t n) {
  std::ifstream in(p, std::ios::binary);
  std::string s(n, '\0');
  in.read(s.data(), static_cast<std::streamsize>(n));
  s.resize(static_cast<std::size_t>(in.gcount()));
  return s;
}

LineChart two_curves() {
  LineChart c;
  c.axes = {"test chart", "speed v (m/s)", "cost of transport (-)", true};
  Series a{"foot A", {}, {}, true, false, std::nullopt};
  Series b{"foot B", {}, {}, false, true, std::nullopt};
  for (int i = 0; i <= 20; ++i) {
    const double v = 0.3 + 0.1 * i;
    a.x.push_back(v);
    a.y.push_back(0.1 + 0.05 * (v - 1.2) * (v - 1.2));
    b.x.push_back(v);
    b.y.push_back(i == 10 ? std::nan("") : 0.15 + 0.03 * v);  // a gap: no solution at one speed
  }
  c.series = {a, b};
  return c;
}

TEST(NiceTicks, CoverTheRangeWithRoundSteps) {
  const auto t = nice_ticks({0.3, 2.3}, 6);
  EXPECT_LE(t.front(), 0.3);
  EXPECT_GE(t.back(), 2.3);
  EXPECT_GE(t.size(), 4u);
  EXPECT_LE(t.size(), 12u);
  const double step = t[1] - t[0];
  const double mantissa = step / std::pow(10.0, std::floor(std::log10(step)));
  EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 2.5) < 1e-9 ||
              std::abs(mantissa - 5) < 1e-9)
      << step;
}

// Issue 17: a step length of 0.9818 to 0.9828 m was drawn as a steep line over the whole plot
// (ticks 0.9818 ... 0.9828); the axis must span at least kMinRelativeSpan of the value.
TEST(ValueRange, NearConstantValuesReadAsFlat) {
  const std::vector<double> ys{0.9818, 0.9822, 0.9828};
  const Range r = value_range(ys);
  EXPECT_LE(r.lo, 0.9818);
  EXPECT_GE(r.hi, 0.9828);
  EXPECT_GE(r.hi - r.lo, 0.1 * 0.9828 - 1e-12);
  EXPECT_NEAR(0.5 * (r.lo + r.hi), 0.9823, 1e-12);  // widened about the data, not shifted
  const std::vector<double> t = nice_ticks(r, 6);
  EXPECT_GE(t[1] - t[0], 0.01) << "ticks at the 0.1 mm scale of the variation";
}

TEST(ValueRange, VaryingValuesKeepTheirFittedRange) {
  const std::vector<double> ys{0.2, 0.9, std::nan("")};  // non-finite values are ignored
  const Range r = value_range(ys);
  EXPECT_NEAR(r.lo, 0.2 - 0.05 * 0.7, 1e-12);
  EXPECT_NEAR(r.hi, 0.9 + 0.05 * 0.7, 1e-12);
}

TEST(LineChart, PngHasRequestedSizeAndEveryCurveColour) {
  const fs::path p = out_dir() / "chart.png";
  render(two_curves(), p.string(), {800, 500});
  const testing::PngImage img = testing::inspect_png(p.string());
  EXPECT_EQ(img.width, 800);
  EXPECT_EQ(img.height, 500);
  EXPECT_GT(img.drawn_pixels, 5000);  // frame, ticks, labels, curves
  EXPECT_GT(img.count(palette(0)), 300) << "curve A missing";
  EXPECT_GT(img.count(palette(1)), 150) << "curve B missing";
}

TEST(LineChart, SvgAndPdfAreWritten) {
  const fs::path svg = out_dir() / "chart.svg", pdf = out_dir() / "chart.pdf";
  render(two_curves(), svg.string());
  render(two_curves(), pdf.string());
  const std::string s = head_of(svg, 4096);
  EXPECT_NE(s.find("<svg"), std::string::npos);
  EXPECT_NE(s.find("width=\"900"), std::string::npos);
  EXPECT_EQ(head_of(pdf, 5), "%PDF-");
  EXPECT_GT(fs::file_size(svg), 5000u);
}

TEST(LineChart, RejectsBadInput) {
  LineChart c = two_curves();
  EXPECT_THROW(render(c, (out_dir() / "chart.jpg").string()), std::invalid_argument);
  c.series[0].y.pop_back();
  EXPECT_THROW(render(c, (out_dir() / "bad.png").string()), std::invalid_argument);
  EXPECT_THROW(render(two_curves(), "/nonexistent-dir/x.png"), std::runtime_error);
}

TEST(FootFigures, ShapeShowsOutlinePolygonAnkleAndCentreOfMass) {
  foot::FootSpec spec = foot::foot_preset("P2-shoes-left-HMT").spec;
  spec.density = 36.9;
  const Scene scene = foot_shape_scene(spec);
  ASSERT_EQ(scene.shapes.size(), 2u);
  EXPECT_GT(scene.shapes[0].points.size(), 200u);
  ASSERT_EQ(scene.markers.size(), 2u);
  const fs::path p = out_dir() / "foot_shape.png";
  render(scene, p.string());
  const testing::PngImage img = testing::inspect_png(p.string());
  EXPECT_EQ(img.width, 900);
  EXPECT_GT(img.count(palette(0)), 400) << "outline missing";
  EXPECT_GT(img.count(palette(3)), 30) << "centre-of-mass marker missing";
  // The outline lies inside the polygon's bounding box grown by the rounding.
  for (const auto& pt : scene.shapes[0].points) {
    EXPECT_GT(pt[0], -0.09);
    EXPECT_LT(pt[0], 0.27);
    EXPECT_LT(pt[1], 0.001);
  }
}

TEST(FootFigures, AnkleTrajectoryChartHasBothCurves) {
  const LineChart c = ankle_trajectory_chart(foot::foot_preset("P1-barefoot-left-HM").spec);
  ASSERT_EQ(c.series.size(), 2u);
  const fs::path p = out_dir() / "ankle.png";
  render(c, p.string());
  const testing::PngImage img = testing::inspect_png(p.string());
  EXPECT_GT(img.count(palette(0)), 300);
  EXPECT_GT(img.count(palette(1)), 150);
}

// Issue 54: sub- and superscripts and Greek letters in figure text and the report.
TEST(RichText, SubAndSuperscriptsAreSmallerShiftedRunsInFiguresAndSubSupInHtml) {
  const std::vector<TextRun> runs = rich_text_runs("x_{H}^{−} − x_{H}^{+} (kg/m^{2}) f_mech a_{b");
  ASSERT_EQ(runs.size(), 9u);
  EXPECT_EQ(runs[0].text, "x");
  EXPECT_EQ(runs[1].text, "H");
  EXPECT_EQ(runs[1].shift, -1);
  EXPECT_EQ(runs[2].text, "−");
  EXPECT_EQ(runs[2].shift, 1);
  EXPECT_EQ(runs[3].text, " − x");
  EXPECT_EQ(runs[7].text, "2");
  EXPECT_EQ(runs[7].shift, 1);
  EXPECT_EQ(runs[8].text, ") f_mech a_{b") << "plain underscores and an unclosed brace stay text";
  EXPECT_EQ(rich_text_html("Λ < 1, x_{H}^{−} & m^{2}"), "Λ &lt; 1, x<sub>H</sub><sup>−</sup> &amp; m<sup>2</sup>");
  EXPECT_EQ(rich_text_plain("x_{H}^{+}"), "x_H^+");
  EXPECT_EQ(rich_text_plain("f_{mech} in kg/m^{2}"), "f_mech in kg/m^2");
  // Drawn: the raised or lowered run is smaller than the same letters on the baseline, and the
  // markup's braces are not drawn.
  Canvas c((out_dir() / "rich_text.png").string(), 200, 60);
  EXPECT_LT(c.text_width("x_{H}", 14), c.text_width("xH", 14));
  EXPECT_GT(c.text_width("x_{H}", 14), c.text_width("x", 14));
  EXPECT_LT(c.text_width("m^{2}", 14), c.text_width("m2", 14));
}

}  // namespace
}  // namespace cyclopt::plot

#include "cyclopt/plot/html_report.hpp"

namespace cyclopt::plot {
namespace {

TEST(HtmlReport, SelfContainedWithEscapedTextTablesAndInlineFigures) {
  Report r;
  r.title = "job 7 <sweep>";
  r.subtitle = "machine & date";
  ReportSection s;
  s.heading = "Results";
  s.listings.push_back({"Resolved spec", R"({"foot": "P2 & co"})"});
  ReportTable table;
  table.header = {"v (m/s)", "f_mech"};
  table.rows = {{"0.3", "0.12"}, {"1.3", "0.08"}};
  table.failed = {false, true};
  s.tables.push_back(table);
  ReportFigure figure;
  figure.caption = "cost of transport";
  figure.svg = svg_of(two_curves());
  s.figures.push_back(figure);
  r.sections.push_back(s);
  const std::string html = to_html(r);
  EXPECT_NE(html.find("<tr class=\"failed\"><td>1.3</td>"), std::string::npos) << "the failed row is marked";
  EXPECT_NE(html.find("<tr><td>0.3</td>"), std::string::npos);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("job 7 &lt;sweep&gt;"), std::string::npos);
  EXPECT_NE(html.find("P2 &amp; co"), std::string::npos);
  EXPECT_NE(html.find("<td>1.3</td><td>0.08</td>"), std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_EQ(html.find("<?xml"), std::string::npos);       // inlined, not a separate document
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);  // nothing external
  EXPECT_EQ(html.find("<img"), std::string::npos);
  EXPECT_NE(html.find("<summary>Resolved spec</summary><pre>"), std::string::npos);
  const fs::path p = out_dir() / "report.html";
  write_html(r, p.string());
  EXPECT_GT(fs::file_size(p), 5000u);
}

// The report's one script (report_script: animations run only on screen) is there only when a
// figure is animated.
TEST(HtmlReport, HoldsItsScriptOnlyWhenAFigureIsAnimated) {
  Report report;
  report.title = "t";
  ReportSection section;
  section.heading = "h";
  ReportFigure still;
  still.svg = "<svg xmlns=\"http://www.w3.org/2000/svg\"><rect width=\"1\" height=\"1\"/></svg>";
  section.figures.push_back(still);
  report.sections.push_back(section);
  const std::string script = "<script>" + report_script() + "</script>";
  EXPECT_EQ(to_html(report).find("<script"), std::string::npos);
  ReportFigure moving;
  moving.svg = "<svg xmlns=\"http://www.w3.org/2000/svg\"><rect width=\"1\" height=\"1\"><animate attributeName=\"width\" "
               "from=\"0\" to=\"1\" dur=\"1s\"/></rect></svg>";
  report.sections.front().figures.push_back(moving);
  const std::string html = to_html(report);
  EXPECT_NE(html.find(script), std::string::npos);
  EXPECT_EQ(html.find("<script"), html.rfind("<script"));  // that one script only
}

}  // namespace
}  // namespace cyclopt::plot
