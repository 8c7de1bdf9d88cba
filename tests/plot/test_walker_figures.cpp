// Pictures of walker jobs (issue 7): the drawing kinematics agree with the walker's own geometry
// (segment lengths, the rolling foot touching the ground at the contact point), every plot kind
// renders from stored results into valid, non-trivial PNG and SVG files, and `cyclopt plot` /
// `cyclopt report` work on a results database written through the store API.
// The gaits are automatic starting gaits (walker::starting_gait), real but not optimal: cheap.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/io/task_spec_json.hpp"
#include "cyclopt/plot/foot_figures.hpp"
#include "cyclopt/plot/gait_energy.hpp"
#include "cyclopt/plot/gait_animation.hpp"
#include "cyclopt/plot/gait_stroboscope.hpp"
#include "cyclopt/plot/giant_swing_stroboscope.hpp"
#include "cyclopt/plot/pdf_report.hpp"
#include "cyclopt/plot/point_diagnostics.hpp"
#include "cyclopt/plot/speed_charts.hpp"
#include "cyclopt/plot/step_figures.hpp"
#include "cyclopt/plot/svg_ids.hpp"
#include "cyclopt/plot/walker_figures.hpp"
#include "cyclopt/plot/walker_job_report.hpp"
#include "cyclopt/plot/walker_pose.hpp"
#include "cyclopt/records/sweep_records.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"
#include "cyclopt/storage/result_store.hpp"
#include "cyclopt/walker/gait_evaluation.hpp"
#include "cyclopt/walker/starting_gait.hpp"
#include "png_inspection.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace cyclopt::plot {
namespace {

namespace fs = std::filesystem;

fs::path out_dir() { return testing::output_dir("cyclopt_test_walker_figures"); }

std::string text_of(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// cairo writes colours into SVG as rgb(r%,g%,b%) with the shortest decimals.
std::string svg_colour(const Color& c) {
  char b[96];
  std::snprintf(b, sizeof b, "rgb(%g%%,%g%%,%g%%)", c.r * 100, c.g * 100, c.b * 100);
  return b;
}

// The inline <svg>...</svg> elements of an HTML page, in order.
std::vector<std::string> inline_svgs(const std::string& html) {
  std::vector<std::string> svgs;
  for (std::size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) {
    const std::size_t end = html.find("</svg>", at);
    if (end == std::string::npos) break;
    svgs.push_back(html.substr(at, end + 6 - at));
  }
  return svgs;
}

// Inline SVGs share one id space: every id on the page is defined once, and each figure's
// references (glyph <use>, clip paths) resolve to an element of the same figure, so each figure
// draws its own letters. Returns the number of ids checked.
std::size_t expect_ids_unique_per_page(const std::string& html) {
  const std::vector<std::string> all = svg_ids(html);
  std::set<std::string> seen;
  for (const std::string& id : all) EXPECT_TRUE(seen.insert(id).second) << "id '" << id << "' defined twice on the page";
  const std::vector<std::string> svgs = inline_svgs(html);
  for (std::size_t k = 0; k < svgs.size(); ++k) {
    const std::vector<std::string> own = svg_ids(svgs[k]);
    const std::set<std::string> defined(own.begin(), own.end());
    for (const std::string& ref : svg_id_references(svgs[k]))
      EXPECT_TRUE(defined.count(ref)) << "figure " << k + 1 << " refers to '" << ref << "', not one of its own ids";
  }
  return all.size();
}

struct StoredJob {
  nlohmann::json spec;
  std::vector<storage::SolutionPoint> points;
};

// Starting gaits of a foot at the speeds, stored by the walker kinds' writer (service/walker_points.hpp).
StoredJob starting_gaits(const std::string& foot, const std::vector<double>& speeds, const std::string& name) {
  StoredJob job;
  job.spec = {{"scene", "walker"}, {"task", "sweep"}, {"foot", foot}, {"speeds", speeds}, {"name", name}};
  const walker::GaitEvaluator ev(walker::make_walker_model(foot::foot_preset(foot).spec));
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    walker::StartingGaitOptions so;
    so.speed = speeds[i];
    const walker::StartingGait sg = walker::starting_gait(ev, so);
    EXPECT_TRUE(sg.real) << foot << " at " << speeds[i] << " m/s: " << sg.message;
    job.points.push_back(jobs::point_of(sg.gait, {sg.x, "starting gait"}, {0, static_cast<int>(i)}, speeds[i]));
  }
  return job;
}

// The job as `cyclopt export` writes it (query rows of result_queries.cpp).
nlohmann::json document_of(std::int64_t id, const StoredJob& job) {
  nlohmann::json d = {{"id", id}, {"scene", "walker"}, {"task", "sweep"}, {"state", "done"}, {"spec", job.spec}};
  d["solutions"] = nlohmann::json::array();
  d["trajectories"] = nlohmann::json::array();
  for (const storage::SolutionPoint& p : job.points) {
    d["solutions"].push_back({{"curve", 0}, {"point", p.key.point_index}, {"parameter", p.parameter},
                              {"status", p.status}, {"values", p.values()}});
    d["trajectories"].push_back({{"curve", 0}, {"point", p.key.point_index}, {"format", "json"}, {"data", *p.trajectory()}});
  }
  return d;
}

class WalkerFigures : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    point_feet_ = new StoredJob(starting_gaits("point", {0.9, 1.0, 1.1}, "point feet"));
    hmt_ = new StoredJob(starting_gaits("P2-shoes-left-HMT", {1.0, 1.2}, "P2 HMT foot"));
  }
  static void TearDownTestSuite() {
    delete point_feet_;
    delete hmt_;
  }
  static std::vector<WalkerJobResults> both() {
    return {walker_job_results(document_of(1, *point_feet_)), walker_job_results(document_of(2, *hmt_))};
  }
  static StoredJob* point_feet_;
  static StoredJob* hmt_;
};
StoredJob* WalkerFigures::point_feet_ = nullptr;
StoredJob* WalkerFigures::hmt_ = nullptr;

TEST_F(WalkerFigures, PoseHasTheModelsSegmentLengthsAndTheFootRollsOnTheGround) {
  const WalkerJobResults r = walker_job_results(document_of(2, *hmt_));
  const walker::WalkerModel<double> m = r.walker.model();
  const std::vector<Xz> outline = foot_outline(r.walker.foot);
  const std::vector<std::vector<double>>& q = r.points[0].trajectory->q;
  auto dist = [](const Xz& a, const Xz& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); };
  for (std::size_t i = 0; i < q[0].size(); i += 40) {
    walker::CoordinateVector<double> qi(static_cast<Eigen::Index>(q.size()));
    for (std::size_t k = 0; k < q.size(); ++k) qi(static_cast<Eigen::Index>(k)) = q[k][i];
    const WalkerPose p = walker_pose(m, qi, outline);
    EXPECT_NEAR(dist(p.hip, p.knee1), m.segments[walker::l_O], 1e-12);
    EXPECT_NEAR(dist(p.knee1, p.ankle1), m.segments[walker::l_U], 1e-12);
    EXPECT_NEAR(dist(p.hip, p.knee2), m.segments[walker::l_O], 1e-12);
    EXPECT_NEAR(dist(p.knee2, p.ankle2), m.segments[walker::l_U], 1e-12);
    EXPECT_NEAR(dist(p.hip, p.torso_tip), m.segments[walker::l_T], 1e-12);
    // The turned outline (mass_properties.hpp) touches the ground exactly at the rolling contact
    // point of eq. 5.4-5.5, and the swing foot's lowest outline point is C2.
    const auto lowest = [](const std::vector<Xz>& pts) {
      return *std::min_element(pts.begin(), pts.end(), [](const Xz& a, const Xz& b) { return a[1] < b[1]; });
    };
    const Xz c1 = lowest(p.foot1), c2 = lowest(p.foot2);
    EXPECT_NEAR(p.contact[1], 0.0, 1e-12);
    EXPECT_NEAR(c1[1], 0.0, 2e-4);
    EXPECT_NEAR(c1[0], p.contact[0], 0.01);
    EXPECT_NEAR(c2[1], p.swing_lowest[1], 2e-4);
    EXPECT_NEAR(p.hip[0], r.points[0].trajectory->hip[0][i], 1e-12);
  }
}

TEST_F(WalkerFigures, EveryKindRendersValidNonTrivialPngAndSvg) {
  const std::vector<WalkerJobResults> jobs = both();
  const std::vector<Figure> figures = walker_figures(jobs, 1.0);
  ASSERT_EQ(figures.size(), walker_figure_kinds().size());
  for (const Figure& f : figures) {
    SCOPED_TRACE(f.name);
    const std::vector<std::string> paths = write_figure(f, out_dir().string());
    const testing::PngImage img = testing::inspect_png(paths[0]);
    EXPECT_EQ(img.width, static_cast<int>(f.options.width));
    EXPECT_EQ(img.height, static_cast<int>(f.options.height));
    const double drawn = double(img.drawn_pixels) / (img.width * img.height);
    EXPECT_GT(drawn, 0.03);
    EXPECT_LT(drawn, 0.8);
    const std::string svg = text_of(paths[1]);
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    EXPECT_GT(svg.size(), 10000u);
  }
  // Charts: one curve per job with both jobs' colours in the SVG; torques: one curve per joint.
  const LineChart& cot = std::get<LineChart>(figures[0].drawing);
  ASSERT_EQ(cot.series.size(), 2u);
  EXPECT_EQ(cot.series[0].label, "point feet");
  EXPECT_EQ(cot.series[1].x.size(), 2u);
  const std::string cot_svg = text_of(out_dir() / "cost_of_transport.svg");
  EXPECT_NE(cot_svg.find(svg_colour(palette(0))), std::string::npos);
  EXPECT_NE(cot_svg.find(svg_colour(palette(1))), std::string::npos);
  EXPECT_EQ(std::get<LineChart>(figures[1].drawing).series.size(), 4u + 6u);
  for (const char* name : {"cost_of_transport", "max_torques", "step_length", "floquet_multiplier"}) {
    const testing::PngImage img = testing::inspect_png((out_dir() / (std::string(name) + ".png")).string());
    EXPECT_GT(img.count(palette(0)), 150) << name;
    EXPECT_GT(img.count(palette(1)), 150) << name;
  }
}

TEST_F(WalkerFigures, ASweepWithSeveralSeedsShadesItsSpreadOnTheCostOfTransport) {
  nlohmann::json doc = document_of(2, *hmt_);
  EXPECT_TRUE(cost_of_transport_chart({walker_job_results(doc)}).bands.empty()) << "one seed: no band";
  records::SweepBestRecord best;
  best.closure = "closed";
  best.seed_spread = 0.1;
  for (nlohmann::json& s : doc["solutions"]) s["values"].update(nlohmann::json(best));
  const std::vector<WalkerJobResults> jobs = {walker_job_results(document_of(1, *point_feet_)), walker_job_results(doc)};
  const LineChart chart = cost_of_transport_chart(jobs);
  ASSERT_EQ(chart.bands.size(), 1u) << "only the job with several seeds";
  const Band& band = chart.bands[0];
  EXPECT_EQ(band.low, chart.series[1].y);
  ASSERT_EQ(band.high.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_DOUBLE_EQ(band.high[i], 1.1 * band.low[i]);
  EXPECT_EQ(band.color.r, palette(1).r) << "the band has its series' colour";
  EXPECT_NE(chart.series[1].label.find("spread over the seeds, at most 10.0 %"), std::string::npos) << chart.series[1].label;
  EXPECT_EQ(chart.series[0].label.find("spread"), std::string::npos);
}

TEST_F(WalkerFigures, StroboscopeShowsGroundContactPointsFeetAndClearance) {
  const std::vector<WalkerJobResults> jobs = {walker_job_results(document_of(2, *hmt_))};
  const Figure f = walker_figure("stroboscope", jobs, 1.2);
  const Scene& s = std::get<Scene>(f.drawing);
  ASSERT_TRUE(s.ground_z);
  EXPECT_EQ(*s.ground_z, 0.0);
  int contacts = 0, clearance = 0, closed = 0;
  for (const Marker& m : s.markers) contacts += m.color.r == 0.84 && m.radius == 4.0;
  for (const Shape& sh : s.shapes) {
    clearance += sh.dashed;
    closed += sh.closed;
  }
  EXPECT_EQ(contacts, 7);     // 1 step x 6 intervals + 1, as in Fig. 9.2
  EXPECT_EQ(clearance, 1);    // one path per step
  EXPECT_EQ(closed, 2 * 7);   // both feet in every frame
  // The contact point moves forwards along the sole during the step.
  EXPECT_LT(s.markers[0].x, s.markers[2 * 6].x);
  // Its own folder: ctest runs the tests of this file in parallel.
  const std::vector<std::string> paths = write_figure(f, (out_dir() / "stroboscope_test").string());
  const testing::PngImage img = testing::inspect_png(paths[0]);
  EXPECT_GT(img.count({0.84, 0.15, 0.16, 1}, 0.1), 100) << "contact points";
  EXPECT_GT(img.count({0.17, 0.63, 0.17, 1}, 0.1), 100) << "clearance path";
  EXPECT_GT(img.count({0.35, 0.25, 0.15, 1}, 0.1), 300) << "ground";
  // Its legend names them (markup of rich_text.hpp).
  std::set<std::string> legends;
  for (const Marker& m : s.markers) legends.insert(m.legend);
  for (const Shape& sh : s.shapes) legends.insert(sh.legend);
  EXPECT_TRUE(legends.count("contact point C_{1}"));
  EXPECT_EQ(std::count_if(legends.begin(), legends.end(), [](const std::string& l) { return l.rfind("swing foot C_{2}", 0) == 0; }), 1);
}

// Issue 54: the stroboscope's x axis is physical, as in Fig. 9.2 (issue 17 had moved every pose
// right by a "spread" so they stood side by side): each pose stands where it is, x = 0 at the
// stance ankle at the impact, and the swing foot's path is the stored one, point by point.
TEST_F(WalkerFigures, StroboscopeDrawsEveryPoseWhereItIsOnAPhysicalAxis) {
  const WalkerJobResults r = walker_job_results(document_of(2, *hmt_));
  const GaitPoint& p = *point_near(r, 1.2);
  const records::GaitTrajectoryRecord& tr = *p.trajectory;
  const Scene s = gait_stroboscope(r, p);
  ASSERT_EQ(s.markers.size(), 2u * 7);  // the contact point and the hip of each of 7 poses
  EXPECT_DOUBLE_EQ(s.markers[1].x, tr.hip[0].front()) << "the hip at the impact starting the step";
  EXPECT_DOUBLE_EQ(s.markers[13].x, tr.hip[0].back()) << "the hip at the impact ending it";
  for (std::size_t f = 1; f < 7; ++f) EXPECT_LT(s.markers[2 * f - 1].x, s.markers[2 * f + 1].x) << "the hip moves on";
  const Shape& path = s.shapes.back();
  ASSERT_TRUE(path.dashed);
  ASSERT_EQ(path.points.size(), tr.swing_contact[0].size());
  for (std::size_t i = 0; i < path.points.size(); ++i) {
    EXPECT_EQ(path.points[i][0], tr.swing_contact[0][i]);
    EXPECT_EQ(path.points[i][1], tr.swing_contact[1][i]);
  }
  EXPECT_EQ(s.axes.x_label.find("spread"), std::string::npos) << s.axes.x_label;
}

TEST_F(WalkerFigures, UnknownKindsAndPointFeetFootFigureAreRejected) {
  const std::vector<WalkerJobResults> jobs = {walker_job_results(document_of(1, *point_feet_))};
  EXPECT_THROW(walker_figure("pie", jobs), std::invalid_argument);
  EXPECT_THROW(walker_figure("foot", jobs), std::invalid_argument);
  EXPECT_EQ(walker_figures(jobs).size(), walker_figure_kinds().size() - 1);  // all but the foot
  EXPECT_THROW(walker_job_results({{"id", 3}, {"scene", "walker"}, {"task", "foot_sweep"}}), std::invalid_argument);
}

// The figures of a walker job's report (walker_job_report.hpp): the solution curves and every kind
// over speed but the stroboscope; five within-step charts (four for point feet); a stroboscope
// of the slowest, chosen and fastest converged gait (as many as differ); an animation per
// converged gait.
std::size_t report_svgs(const WalkerJobResults& r) {
  std::size_t animated = 0;
  for (const GaitPoint& p : r.points) animated += p.converged && p.trajectory;
  const bool feet = r.walker.foot.model != foot::FootModel::point;
  return walker_figure_kinds().size() - (feet ? 0 : 1) + (feet ? 5 : 4) + std::min<std::size_t>(animated, 3) + animated;
}

TEST_F(WalkerFigures, ReportIsOneSelfContainedPageWithTableAndFigures) {
  const std::string html = to_html(walker_job_report(document_of(2, *hmt_)));
  EXPECT_NE(html.find("<h2>Provenance</h2>"), std::string::npos);
  EXPECT_NE(html.find("P2-shoes-left-HMT"), std::string::npos);
  EXPECT_NE(html.find("<td>1.200</td>"), std::string::npos);
  EXPECT_EQ(inline_svgs(html).size(), report_svgs(walker_job_results(document_of(2, *hmt_))));
  EXPECT_EQ(html.find("src=\""), std::string::npos);  // nothing external
}

// Issue 17: the report animates the gait of every converged speed with SMIL alone: torso, two legs
// and two feet, each one element whose points step through the poses of two steps in real time.
// Its one script only pauses the animations off screen (report_script); without it they run.
TEST_F(WalkerFigures, ReportAnimatesEveryConvergedGaitWithoutJavaScript) {
  const WalkerJobResults r = walker_job_results(document_of(2, *hmt_));
  const std::string html = to_html(walker_job_report(document_of(2, *hmt_)));
  EXPECT_NE(html.find("<h2>Gait animations</h2>"), std::string::npos);
  EXPECT_EQ(html.find("<script"), html.find("<script>" + report_script() + "</script>"));
  EXPECT_EQ(html.find("<script"), html.rfind("<script"));
  std::size_t animates = 0;
  for (std::size_t at = html.find("<animate attributeName=\"points\""); at != std::string::npos;
       at = html.find("<animate attributeName=\"points\"", at + 1))
    ++animates;
  std::size_t converged = 0;
  for (const GaitPoint& p : r.points) converged += p.converged && p.trajectory;
  EXPECT_EQ(animates, 5 * converged);  // torso, legs A and B, feet A and B
  const GaitPoint& p = *point_near(r, 1.2);
  const std::string svg = gait_animation_svg(r, p, 10);
  // 2 steps of 10 intervals: 21 poses, each a list of points; the loop lasts two step periods.
  const std::size_t values = svg.find("values=\"");
  ASSERT_NE(values, std::string::npos);
  const std::string first = svg.substr(values + 8, svg.find('"', values + 8) - values - 8);
  EXPECT_EQ(std::count(first.begin(), first.end(), ';'), 20);
  char dur[48];
  std::snprintf(dur, sizeof dur, "dur=\"%.4fs\"", 2 * p.trajectory->time.back());
  EXPECT_NE(svg.find(dur), std::string::npos) << dur;
  EXPECT_THROW(gait_animation_svg(r, p, 0), std::invalid_argument);
  expect_ids_unique_per_page(html);
}

// Issue 17 item 9: the animation is drawn at a readable size and says what it shows and when: the
// gait's speed and step, a clock reading the time in the loop and a bar filling over it.
TEST_F(WalkerFigures, GaitAnimationHasAClockATimeBarAndItsGaitLabel) {
  const WalkerJobResults r = walker_job_results(document_of(2, *hmt_));
  const GaitPoint& p = *point_near(r, 1.2);
  const std::string svg = gait_animation_svg(r, p, 10);
  const double width = std::stod(svg.substr(svg.find("width=\"") + 7));
  const double height = std::stod(svg.substr(svg.find("height=\"") + 8));
  EXPECT_GE(height, 300) << "the walker is drawn 230 px high";
  EXPECT_LE(width, 470) << "two animations fit side by side on the 980 px page";
  // Issue 54: the gait's label is the grid's caption, once, not also inside the animation.
  char label[160];
  std::snprintf(label, sizeof label, "v = %.2f m/s, step length %.3f m, T = %.3f s", p.gait.mean_speed,
                p.gait.step_length, p.gait.step_period);
  EXPECT_EQ(svg.find("step length"), std::string::npos);
  const std::string page = to_html(walker_job_report(document_of(2, *hmt_)));
  const std::string caption = std::string("<figcaption>") + label + "</figcaption>";
  const std::size_t grid = page.find("<h2>Gait animations</h2>");
  ASSERT_NE(grid, std::string::npos);
  EXPECT_NE(page.find("<div class=\"grid\">", grid), std::string::npos) << "the animations stand in a grid";
  EXPECT_NE(page.find(caption, grid), std::string::npos) << caption;
  EXPECT_EQ(page.find(caption, page.find(caption, grid) + 1), std::string::npos) << "one caption per animation";
  // The clock: one text per interval of the 2 x 10 poses, "t = 0.00 s" first (the static picture's),
  // each visible during its interval of the loop.
  const std::size_t clock = svg.find("<g id=\"gait-clock\"");
  ASSERT_NE(clock, std::string::npos);
  const std::string clock_group = svg.substr(clock, svg.find("</g>", clock) - clock);
  std::size_t texts = 0;
  for (std::size_t at = clock_group.find("<text"); at != std::string::npos; at = clock_group.find("<text", at + 1)) ++texts;
  EXPECT_EQ(texts, 20u);
  EXPECT_NE(clock_group.find("visibility=\"visible\">t = 0.00 s<animate attributeName=\"visibility\""), std::string::npos);
  char last[48];
  std::snprintf(last, sizeof last, "t = %.2f s", 19 * p.trajectory->time.back() / 10);
  EXPECT_NE(clock_group.find(last), std::string::npos) << last;
  char dur[48];
  std::snprintf(dur, sizeof dur, "dur=\"%.4fs\"", 2 * p.trajectory->time.back());
  std::size_t clocked = 0;
  for (std::size_t at = clock_group.find(dur); at != std::string::npos; at = clock_group.find(dur, at + 1)) ++clocked;
  EXPECT_EQ(clocked, 20u) << "every clock text runs with the gait's loop";
  // The bar fills over the same loop and is marked at T.
  const std::size_t bar = svg.find("<g id=\"gait-time-bar\"");
  ASSERT_NE(bar, std::string::npos);
  const std::string bar_group = svg.substr(bar, svg.find("</g>", bar) - bar);
  EXPECT_NE(bar_group.find("<animate attributeName=\"width\" from=\"0\""), std::string::npos);
  EXPECT_NE(bar_group.find(dur), std::string::npos);
  char period[48];
  std::snprintf(period, sizeof period, "T = %.3f s", p.trajectory->time.back());
  EXPECT_NE(bar_group.find(period), std::string::npos);
  // Several animations on one page keep their clocks apart (svg_ids.hpp).
  const std::string html = to_html(walker_job_report(document_of(2, *hmt_)));
  std::size_t clocks = 0;
  for (const std::string& id : svg_ids(html)) clocks += id.find("gait-clock") != std::string::npos;
  EXPECT_EQ(clocks, 2u);
  expect_ids_unique_per_page(html);
}

// Issue 17: cairo names glyphs "glyph0-1" ... in every SVG; inlined unchanged, figures 2-5 of a
// report drew figure 1's letters ("Cost ofrantphrhmei ml gr").
TEST_F(WalkerFigures, ReportFiguresHaveIdsUniqueOnThePageAndDrawTheirOwnGlyphs) {
  const std::string html = to_html(walker_job_report(document_of(2, *hmt_)));
  const std::vector<std::string> svgs = inline_svgs(html);
  // The figures, then one gait animation (its text not cairo's: no glyphs) per converged speed
  // (1.0 and 1.2 m/s).
  ASSERT_EQ(svgs.size(), report_svgs(walker_job_results(document_of(2, *hmt_))));
  for (std::size_t i = 0; i < walker_figure_kinds().size(); ++i)
    ASSERT_NE(svgs[i].find("glyph"), std::string::npos) << "a figure without text";
  // The figures as cairo wrote them do share ids (the failure this guards against) ...
  const std::vector<Figure> figures = walker_figures({walker_job_results(document_of(2, *hmt_))});
  const std::vector<std::string> raw1 = svg_ids(svg_of(figures[0])), raw2 = svg_ids(svg_of(figures[1]));
  ASSERT_FALSE(raw1.empty());
  EXPECT_NE(std::find(raw2.begin(), raw2.end(), raw1.front()), raw2.end());
  // ... the page does not.
  EXPECT_GT(expect_ids_unique_per_page(html), 50u);
}

// Issue 54 item 4: the report says where its numbers come from, in a box at its top: program
// version, build level and flags, seeds, dates, the resolved and the submitted spec.
TEST_F(WalkerFigures, ReportOpensWithAProvenanceBox) {
  nlohmann::json doc = document_of(2, *hmt_);
  doc["program_version"] = "abc1234";
  doc["isa_level"] = "x86-64-v3";
  doc["build_flags"] = "GNU 12.2.0 -march=x86-64-v3 -O3";
  doc["seeds"] = {{"multistart.seed", 7}};
  doc["submitted_at"] = 1796575209.4;  // 2026-12-06T16:40:09Z
  doc["resolved_spec"] = doc["spec"];
  doc["resolved_spec"]["points"] = 123;  // only the resolved spec holds the default
  const std::string html = to_html(walker_job_report(doc));
  const std::size_t box = html.find("<section class=\"box\"><h2>Provenance</h2>");
  ASSERT_NE(box, std::string::npos);
  const std::string section = html.substr(box, html.find("</section>", box) - box);
  for (const char* text : {"<td>program</td><td>abc1234</td>", "<td>build level (ISA)</td><td>x86-64-v3",
                           "GNU 12.2.0 -march=x86-64-v3 -O3", "{&quot;multistart.seed&quot;:7}",
                           "<td>submitted</td><td>2026-12-06T16:40:09Z</td>", "&quot;points&quot;: 123",
                           "Resolved spec", "Submitted spec"})
    EXPECT_NE(section.find(text), std::string::npos) << text;
  EXPECT_LT(box, html.find("<h2>Solved points")) << "the box comes first";
  // A job stored before the row held them says so rather than showing blanks.
  const std::string old = to_html(walker_job_report(document_of(2, *hmt_)));
  EXPECT_NE(old.find("<td>program</td><td>not recorded"), std::string::npos);
}

// Issue 54 item 4: one diagnostics row per stored point of every curve, numbered as `cyclopt query`
// numbers them, a point whose solve did not converge marked.
TEST_F(WalkerFigures, DiagnosticsTableHasOneRowPerStoredPointAndMarksTheFailedOne) {
  nlohmann::json doc = document_of(2, *hmt_);
  nlohmann::json on_curve_1 = doc["solutions"][0];
  on_curve_1["curve"] = 1;
  doc["solutions"].push_back(on_curve_1);
  nlohmann::json& failed = doc["solutions"][1]["values"];
  failed["solver"] = {{"termination", "max_iterations"}, {"success", false}, {"message", "MaxIter"},
                      {"iterations", 500}, {"function_evaluations", 600}, {"jacobian_evaluations", 500},
                      {"failed_evaluations", 0}, {"wall_seconds", 12.5}, {"objective", 0.02},
                      {"kkt_error", 3.2e-3}, {"constraint_violation", 1e-9}, {"x", nlohmann::json::array()}};
  doc["solutions"][1]["status"] = "max_iterations";
  const ReportTable t = point_diagnostics_table(doc);
  ASSERT_EQ(t.rows.size(), doc["solutions"].size());
  ASSERT_EQ(t.failed, (std::vector<bool>{false, true, false}));
  EXPECT_EQ(t.rows[2][0], "1") << "curve numbers as stored";
  const std::vector<std::string> row = t.rows[1];
  EXPECT_EQ(row[4], "500");
  EXPECT_EQ(row[5], "3.2e-03");
  EXPECT_EQ(row[7], "12.50");
  EXPECT_EQ(row[9], "max_iterations");
  EXPECT_EQ(row[10], "NO");
  EXPECT_EQ(t.rows[0][10], "yes");
  const std::string html = to_html(walker_job_report(doc));
  std::size_t marked = 0;
  for (std::size_t at = html.find("<tr class=\"failed\">"); at != std::string::npos; at = html.find("<tr class=\"failed\">", at + 1))
    ++marked;
  EXPECT_EQ(marked, 2u) << "the diagnostics row and the solved-points row of the failed speed";
  EXPECT_NE(html.find("3 stored points on 2 curve(s)"), std::string::npos);
  EXPECT_NE(html.find("1 did not converge"), std::string::npos);
}

// Issue 54 item 4: the Floquet chart draws the stability limit |Λ| = 1 (eq. 5.90).
TEST_F(WalkerFigures, FloquetChartDrawsTheStabilityLineAtOne) {
  LineChart chart = floquet_chart({walker_job_results(document_of(2, *hmt_))});
  bool negative = false;
  for (double y : chart.series[0].y) negative = negative || y < 0;
  ASSERT_EQ(chart.reference_lines.size(), negative ? 2u : 1u) << "a line at -1 only for a negative multiplier";
  EXPECT_EQ(chart.reference_lines[0].y, 1.0);
  EXPECT_NE(chart.axes.y_label.find("Λ"), std::string::npos);
  // On a y axis from 0 to 2 the line runs across the middle of the plot area (Axes: 48 px above
  // it with a title, 62 below): at row 48 + (600 - 110) / 2 = 293.
  chart.y_range = Range{0, 2};
  const fs::path png = out_dir() / "floquet_line.png";
  render(chart, png.string(), {900, 600});
  std::map<int, int> in_row;  // pixels of the line's colour (antialiased: within 0.3) per row
  testing::for_pixels_of(png.string(), kReferenceLineColor, 0.3, 0, 600, [&in_row](int, int y) { ++in_row[y]; });
  const auto densest = std::max_element(in_row.begin(), in_row.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  ASSERT_NE(densest, in_row.end());
  EXPECT_NEAR(densest->first, 292.5, 1);
  EXPECT_GT(densest->second, 300) << "a dashed line across the plot";
}

// Issue 54 item 4 (seed 001 Fig. 9.5, section 9.1): within one step the joint powers with their
// positive part shaded, the part f_mech charges: the shaded areas of all joints add up to the
// stored f_mech (eq. 5.100, 5.102: trapezoid rule in time, zero crossings interpolated), and no
// shading where a power is negative.
TEST_F(WalkerFigures, PowerChartShadesExactlyThePositivePartThatFmechCharges) {
  const WalkerJobResults r = walker_job_results(document_of(2, *hmt_));
  const GaitPoint& p = *point_near(r, 1.2);
  const LineChart chart = joint_power_chart(r, p);
  ASSERT_EQ(chart.series.size(), 6u);
  ASSERT_EQ(chart.bands.size(), 6u);
  double shaded = 0;  // sum over joints of the shaded area, in W times t/T
  for (std::size_t j = 0; j < 6; ++j) {
    const Band& b = chart.bands[j];
    const Series& s = chart.series[j];
    for (std::size_t i = 0; i < b.x.size(); ++i) {
      EXPECT_EQ(b.low[i], 0.0);
      EXPECT_GE(b.high[i], 0.0);
    }
    for (std::size_t i = 0; i < s.x.size(); ++i) {  // on the samples: max(P, 0)
      const auto at = std::find(b.x.begin(), b.x.end(), s.x[i]);
      ASSERT_NE(at, b.x.end());
      EXPECT_EQ(b.high[static_cast<std::size_t>(at - b.x.begin())], std::max(s.y[i], 0.0));
    }
    for (std::size_t i = 1; i < b.x.size(); ++i) shaded += 0.5 * (b.high[i - 1] + b.high[i]) * (b.x[i] - b.x[i - 1]);
  }
  const walker::WalkerModel<double> m = r.walker.model();
  const double f_mech = shaded * p.trajectory->time.back() / (m.total_mass * m.constants.gravity * p.gait.step_length);
  EXPECT_NEAR(f_mech, p.gait.f_mech, 1e-9 * p.gait.f_mech);
  const std::vector<Figure> step = within_step_figures(r, p);
  ASSERT_EQ(step.size(), 5u);
  for (const Figure& f : step) {
    SCOPED_TRACE(f.name);
    const std::string path = write_figure(f, (out_dir() / "within_step").string())[0];
    EXPECT_GT(testing::inspect_png(path).drawn_pixels, 20000);
  }
  // Angles in degrees and torques as stored, one curve per joint over t/T in [0, 1].
  const LineChart angles = std::get<LineChart>(step[0].drawing), torques = std::get<LineChart>(step[1].drawing);
  EXPECT_DOUBLE_EQ(angles.series[2].y[5], 180.0 / M_PI * p.trajectory->q[3][5]);
  EXPECT_EQ(torques.series[4].y, p.trajectory->torque[4]);
  EXPECT_EQ(torques.series[4].x.back(), 1.0);
}

// The rolling contact point within the step: on the sole between its heel and toe ends, where the
// placed foot outline touches the ground (walker_pose.hpp).
TEST_F(WalkerFigures, ContactPointChartStaysOnTheSole) {
  const WalkerJobResults r = walker_job_results(document_of(2, *hmt_));
  const GaitPoint& p = *point_near(r, 1.2);
  const LineChart chart = contact_point_chart(r, p);
  ASSERT_EQ(chart.series.size(), 1u);
  ASSERT_EQ(chart.reference_lines.size(), 3u);
  const double toe = chart.reference_lines[0].y, heel = chart.reference_lines[1].y;
  EXPECT_LT(heel, 0.0);
  EXPECT_GT(toe, 0.0);
  for (double c : chart.series[0].y) {
    EXPECT_GT(c, heel);
    EXPECT_LT(c, toe);
  }
  EXPECT_THROW(contact_point_chart(walker_job_results(document_of(1, *point_feet_)), *point_near(walker_job_results(document_of(1, *point_feet_)), 1.0)),
               std::invalid_argument);
}

// Fig. 9.5a and the energy balance of the stance phase: the increase of E_tot = E_pot + E_kin computed
// from the stored q and dq/dt equals the work the joint torques did until then (the rolling contact
// does no work), up to the trapezoid rule's error on the stored grid - an independent check of the
// stored torques, which come from the inverse dynamics, not from the energies. The difference is the
// quadrature's: it shrinks about fourfold per halved step (P = 100 .. 800 on these gaits), and on
// the default grid (P = 200) stays below 0.5 % of the energy's swing.
TEST_F(WalkerFigures, EnergyChartAgreesWithTheWorkOfTheJointTorques) {
  for (const StoredJob* job : {point_feet_, hmt_}) {
    const WalkerJobResults r = walker_job_results(document_of(1, *job));
    const GaitPoint& p = *point_near(r, 1.0);
    const LineChart chart = energy_chart(r, p);
    ASSERT_EQ(chart.series.size(), 2u);
    const std::vector<double>&energy = chart.series[0].y, &work = chart.series[1].y;
    ASSERT_EQ(energy.size(), p.trajectory->time.size());
    EXPECT_EQ(energy.front(), 0.0);
    double scale = 0, worst = 0;
    for (std::size_t k = 0; k < energy.size(); ++k) {
      scale = std::max(scale, std::abs(energy[k]));
      worst = std::max(worst, std::abs(energy[k] - work[k]));
    }
    std::printf("%s at %.1f m/s: max |E_tot - E_tot(0)| %.4f J, max |difference to the work| %.2e J over %zu samples\n",
                r.walker.setup.foot.dump().c_str(), p.speed, scale, worst, energy.size());
    EXPECT_GT(scale, 0.1);  // the energy changes within the step: the test can fail
    EXPECT_LT(worst, 5e-3 * scale);
  }
}

// Fig. 9.5b: the impact's loss relative to E_kin after it. The stored loss (from the impact map's
// momentum balance) equals the drop of E_kin across the step's end computed from the stored
// trajectory: E_kin at its last sample (before the impact) minus E_kin at its first (after the
// previous impact; the gait is periodic).
TEST_F(WalkerFigures, ImpactLossIsTheKineticEnergyTheStepEndsWithAboveItsStart) {
  for (const StoredJob* job : {point_feet_, hmt_}) {
    const WalkerJobResults r = walker_job_results(document_of(1, *job));
    const LineChart chart = impact_loss_chart({r});
    ASSERT_EQ(chart.series.size(), 1u);
    const walker::WalkerModel<double> m = r.walker.model();
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const GaitPoint& p = r.points[i];
      const records::GaitTrajectoryRecord& tr = *p.trajectory;
      const double before = kinetic_energy_at(m, tr, tr.time.size() - 1), after = kinetic_energy_at(m, tr, 0);
      std::printf("%s at %.1f m/s: stored impact loss %.6f J, E_kin before - after %.6f J, %.2f %%\n",
                  r.walker.setup.foot.dump().c_str(), p.speed, p.gait.impact_energy_loss, before - after,
                  chart.series[0].y[i]);
      EXPECT_GT(p.gait.impact_energy_loss, 0.0);
      EXPECT_NEAR(p.gait.impact_energy_loss, before - after, 1e-6 * before);
      EXPECT_DOUBLE_EQ(chart.series[0].y[i], 100.0 * p.gait.impact_energy_loss / after);
    }
  }
}

// Issue 54 item 4 (seed 001 Fig. 9.1): every stored solution curve, numbered as stored, over the
// best-per-speed envelope.
TEST_F(WalkerFigures, SolutionCurvesChartDrawsEveryStoredCurveOverTheEnvelope) {
  nlohmann::json doc = document_of(2, *hmt_);
  const nlohmann::json best = doc["solutions"];
  for (int curve : {1, 3})
    for (const nlohmann::json& s : best) {
      nlohmann::json c = s;
      c["curve"] = curve;
      doc["solutions"].push_back(c);
    }
  const WalkerJobResults r = walker_job_results(doc);
  ASSERT_EQ(r.curves.size(), 2u);
  const LineChart chart = solution_curves_chart(r);
  ASSERT_EQ(chart.series.size(), 3u);
  EXPECT_EQ(chart.series[0].label, "curve 0: best per speed (envelope)");
  EXPECT_GT(chart.series[0].width, chart.series[1].width);
  EXPECT_EQ(chart.series[1].label, "curve 1");
  EXPECT_EQ(chart.series[2].label, "curve 3");
  EXPECT_EQ(chart.series[2].y.size(), 2u);
  EXPECT_EQ(chart.series[2].y[1], r.points[1].gait.objective);
  EXPECT_NE(chart.axes.y_label.find("f_{mech}"), std::string::npos);
}

// Issue 54 item 4: the report as a PDF (cairo): a PDF document whose pages are the text pages and
// one page per drawn figure (the SVG-only animations left out).
TEST_F(WalkerFigures, ReportAsPdfHasAPagePerFigureAfterItsText) {
  const Report report = walker_job_report(document_of(2, *hmt_));
  std::size_t drawn = 0;
  for (const ReportSection& s : report.sections)
    for (const ReportFigure& f : s.figures) drawn += static_cast<bool>(f.draw);
  const WalkerJobResults r = walker_job_results(document_of(2, *hmt_));
  EXPECT_EQ(drawn, report_svgs(r) - 2) << "every figure but the two animations";
  const fs::path pdf = out_dir() / "report.pdf";
  write_pdf(report, pdf.string());
  const std::string bytes = text_of(pdf);
  EXPECT_EQ(bytes.rfind("%PDF-", 0), 0u);
  std::size_t pages = 0;
  for (std::size_t at = bytes.find("/Type /Page"); at != std::string::npos; at = bytes.find("/Type /Page", at + 1))
    pages += bytes.compare(at, 12, "/Type /Pages") != 0;
  EXPECT_GT(pages, drawn) << "text pages, then one per figure";
  EXPECT_LT(pages, drawn + 6);
}

TEST(GiantSwingStroboscope, FramesAtTheRateWithBarHipAndFeetPaths) {
  nlohmann::json result;
  result["task"] = io::to_json(giant_swing::default_task(giant_swing::TaskKind::single_swing));
  result["support_values_Nm"] = {0.0, 60.0, -40.0, 0.0};
  const Scene s = giant_swing_stroboscope(giant_swing::appendix_b_gymnast(), result, 25.0);
  ASSERT_GT(s.shapes.size(), 20u);  // at least 10 frames of two segments, plus two paths
  ASSERT_EQ(s.markers.size(), 1u);
  EXPECT_EQ(s.markers[0].legend, "high bar");
  // The upper body is L1 long in every frame; the first frame is the handstand.
  EXPECT_NEAR(std::hypot(s.shapes[0].points[1][0], s.shapes[0].points[1][1]), giant_swing::appendix_b_gymnast().L1, 1e-12);
  EXPECT_NEAR(s.shapes[0].points[1][0], 0.0, 1e-12);
  const fs::path png = out_dir() / "giant_swing_test.png";
  const RenderOptions size = fitted_options(s, 800);
  // A full circle of swings is about as wide as high (Axes margins 104 + 110 px, legend above).
  EXPECT_NEAR(size.width - 104, 800 - 110 - s.legend_headroom, 100);
  // Issue 17: time and direction cues. Time stamps every 0.2 s (5 frames at 25 Hz) from 0 on, but
  // not on top of an earlier one, each with an arrowhead on the feet path; all arrows turn the same
  // way about the bar; later frames darker.
  ASSERT_GE(s.labels.size(), 3u);
  EXPECT_EQ(s.labels[0].text, "0.0 s");
  for (std::size_t i = 1; i < s.labels.size(); ++i) {
    const double t = std::stod(s.labels[i].text), before = std::stod(s.labels[i - 1].text);
    EXPECT_GT(t, before);
    EXPECT_NEAR(std::remainder(t, 0.2), 0.0, 1e-9) << s.labels[i].text;
    EXPECT_GT(std::hypot(s.labels[i].x - s.labels[i - 1].x, s.labels[i].z - s.labels[i - 1].z), 0.3);
  }
  std::vector<double> turn;  // (position x direction) of each arrowhead: its sense about the bar
  for (const Shape& sh : s.shapes)
    if (sh.legend.rfind("direction of motion", 0) == 0) {
      ASSERT_EQ(sh.points.size(), 3u);
      const double bx = 0.5 * (sh.points[1][0] + sh.points[2][0]), bz = 0.5 * (sh.points[1][1] + sh.points[2][1]);
      turn.push_back(bx * (sh.points[0][1] - bz) - bz * (sh.points[0][0] - bx));
    }
  EXPECT_EQ(turn.size(), s.labels.size());
  for (double c : turn) EXPECT_GT(c * turn.front(), 0) << "an arrow against the swing";
  EXPECT_LT(s.shapes[0].color.a, 0.5);
  render(s, png.string(), size);
  const testing::PngImage img = testing::inspect_png(png.string());
  EXPECT_EQ(img.height, 800);
  EXPECT_GT(img.count({0.12, 0.47, 0.71, 1}), 500) << "upper body";
  EXPECT_GT(img.count({0.84, 0.37, 0.0, 1}), 500) << "legs";
  EXPECT_THROW(giant_swing_stroboscope(giant_swing::appendix_b_gymnast(), {{"task", result["task"]}}),
               std::invalid_argument);
}

// The command line on a database written through the store API (read-only, no server).
TEST_F(WalkerFigures, CommandLinePlotsAndReportsFromADatabase) {
  const fs::path dir = out_dir() / "cli";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string db = (dir / "results.db").string();
  {
    storage::ResultStore store(db);
    for (const StoredJob* job : {point_feet_, hmt_}) {
      const storage::SubmitOutcome s = store.submit("req-" + job->spec["name"].get<std::string>(), "walker", "sweep",
                                                    job->spec.dump());
      for (const storage::SolutionPoint& p : job->points) store.store_point(s.job_id, p);
      store.finish(s.job_id, storage::JobState::done, "", 1.5, 0.0);
    }
  }
  const std::string cli = std::string(CYCLOPT_CLI) + " --db " + db;
  ASSERT_EQ(std::system((cli + " plot all --job 1 --job 2 --out " + (dir / "pictures").string() + " > " +
                         (dir / "plot.txt").string()).c_str()),
            0);
  for (const char* name : {"cost_of_transport", "max_torques", "step_length", "floquet_multiplier", "stroboscope",
                           "foot_shape"}) {
    EXPECT_GT(testing::inspect_png((dir / "pictures" / (std::string(name) + ".png")).string()).drawn_pixels, 10000)
        << name;
    EXPECT_TRUE(fs::exists(dir / "pictures" / (std::string(name) + ".svg"))) << name;
  }
  EXPECT_NE(text_of(dir / "plot.txt").find("stroboscope.png"), std::string::npos);
  ASSERT_EQ(std::system((cli + " report 2 --out " + (dir / "job2.html").string() + " > /dev/null").c_str()), 0);
  EXPECT_NE(text_of(dir / "job2.html").find("<svg"), std::string::npos);
  EXPECT_GT(expect_ids_unique_per_page(text_of(dir / "job2.html")), 50u);
  // Bad input: an unknown kind and a job that does not exist are rejected (exit 2), a plot
  // without jobs is a usage error (exit 1).
  EXPECT_EQ(WEXITSTATUS(std::system((cli + " plot pie --job 1 2> /dev/null").c_str())), 2);
  EXPECT_EQ(WEXITSTATUS(std::system((cli + " report 9 2> /dev/null").c_str())), 2);
  EXPECT_EQ(WEXITSTATUS(std::system((cli + " plot all 2> /dev/null").c_str())), 1);
}

// Issue 17 item 4: `cyclopt query` prints one readable line per point with the quantities users
// look for first; --wide, --csv and --json carry the rest; times are ISO 8601.
TEST_F(WalkerFigures, QueryPrintsOneReadableLinePerPoint) {
  const fs::path dir = out_dir() / "query";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string db = (dir / "results.db").string();
  {
    storage::ResultStore store(db);
    const storage::SubmitOutcome s = store.submit("req-q", "walker", "sweep", point_feet_->spec.dump());
    for (const storage::SolutionPoint& p : point_feet_->points) store.store_point(s.job_id, p);
    store.finish(s.job_id, storage::JobState::done, "", 1.5, 0.0, 3);
  }
  const std::string cli = std::string(CYCLOPT_CLI) + " --db " + db;
  auto output = [&](const std::string& args, const std::string& name) {
    const fs::path file = dir / name;
    EXPECT_EQ(std::system((cli + " " + args + " > " + file.string()).c_str()), 0) << args;
    std::vector<std::string> lines;
    std::istringstream in(text_of(file));
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  };
  const std::vector<std::string> table = output("query 1", "table.txt");
  ASSERT_EQ(table.size(), 1 + point_feet_->points.size());
  for (const char* column : {"speed_m_s", "f_mech", "step_length_m", "period_s", "cadence_1_min", "floquet",
                             "impact_loss_J", "status", "curve"})
    EXPECT_NE(table[0].find(column), std::string::npos) << column << " missing from: " << table[0];
  for (const std::string& line : table) EXPECT_LT(line.size(), 140u) << line;
  // The line of the 1.0 m/s point shows its step length and cadence = 60 / period.
  const nlohmann::json& g = point_feet_->points[1].values().at("gait");
  // Issue 54: fixed decimals per column (step length in 0.1 mm, cadence in 0.1 steps per minute).
  char step[32], cadence[32];
  std::snprintf(step, sizeof step, "%.4f", g["step_length"].get<double>());
  std::snprintf(cadence, sizeof cadence, "%.1f", 60.0 / g["step_period"].get<double>());
  EXPECT_NE(table[2].find(step), std::string::npos) << table[2];
  EXPECT_NE(table[2].find(cadence), std::string::npos) << table[2];
  const std::vector<std::string> wide = output("query 1 --wide", "wide.txt");
  EXPECT_NE(wide[0].find("gait.step_length"), std::string::npos) << wide[0];
  EXPECT_NE(wide[0].find("speed [m/s]"), std::string::npos) << wide[0];
  EXPECT_EQ(wide[0].find("parameter"), std::string::npos) << wide[0];
  EXPECT_NE(wide[0].find("solved_at"), std::string::npos) << wide[0];
  const std::vector<std::string> csv = output("query 1 --csv", "table.csv");
  EXPECT_NE(csv[0].find("gait.floquet_multiplier"), std::string::npos) << csv[0];
  output("query 1 --json", "table.json");
  EXPECT_EQ(nlohmann::json::parse(text_of(dir / "table.json")).size(), point_feet_->points.size());
  const std::vector<std::string> jobs = output("list", "jobs.txt");
  ASSERT_EQ(jobs.size(), 2u);
  // list: ISO 8601 local times to the minute (docs/watching-jobs.md).
  const std::size_t at = jobs[0].find("SUBMITTED");
  ASSERT_NE(at, std::string::npos) << jobs[0];
  const std::string submitted = jobs[1].substr(at, 16);
  ASSERT_EQ(submitted.size(), 16u) << jobs[1];
  EXPECT_EQ(submitted[4], '-') << jobs[1];
  EXPECT_EQ(submitted[10], 'T') << jobs[1];
  EXPECT_EQ(submitted[13], ':') << jobs[1];
}

}  // namespace
}  // namespace cyclopt::plot
