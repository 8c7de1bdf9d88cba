// The foot_design job kind (service/foot_design_kind.hpp, issue 15 item 3): bad design specs are
// refused at submission naming the field and its admissible range (acceptance 6), and a small real
// design through the server stores the reference sweeps, the design multistart's optima, the
// free-foot continuation, the fixed-foot sweeps and one records::DesignedFootRecord per density
// in the layout of records/foot_design_records.hpp.
#include "cyclopt/records/foot_comparison_records.hpp"
#include "cyclopt/plot/foot_design_figures.hpp"
#include "cyclopt/plot/foot_design_report.hpp"
#include "cyclopt/records/foot_design_records.hpp"
#include "cyclopt/service/job_spec.hpp"
#include "memq_server_fixture.hpp"
#include "spec_rejection.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <cstdlib>
#include <cmath>
#include <map>
#include <set>
#include <thread>

namespace cyclopt {
namespace {

using testing::rejection;

nlohmann::json design_spec() { return {{"scene", "walker"}, {"task", "foot_design"}}; }

TEST(FootDesignSpec, TheSeedsStudyIsAcceptedWithItsDefaults) {
  EXPECT_EQ(rejection(design_spec()), "accepted");  // P2-shoes-left-HMT, 10:10:70, 2.3 m/s of 0.3:0.1:2.3
  nlohmann::json s = design_spec();
  s["foot"] = "P1-shoes-left-HM-SG";
  s["free_parameters"] = {"l_HM", "k_HM"};
  s["design_bounds"] = {{"l_HM_max", 0.35}};
  EXPECT_EQ(rejection(s), "accepted");
}

TEST(FootDesignSpec, RefusesBadDesignSpecsNamingTheFieldAndRange) {
  nlohmann::json s = design_spec();
  s["densities"] = {10, -5};
  EXPECT_EQ(rejection(s).rfind("densities", 0), 0u) << rejection(s);
  EXPECT_NE(rejection(s).find("1000"), std::string::npos) << rejection(s);  // the admissible range
  s["densities"] = {10, 10};
  EXPECT_EQ(rejection(s).rfind("densities[1]", 0), 0u) << rejection(s);
  // P2's h_F = 106.5 mm is above h_F,max = 100 mm: with h_F not free the bounds exclude the start foot.
  s = design_spec();
  s["free_parameters"] = {"l_HM", "k_HM"};
  EXPECT_EQ(rejection(s).rfind("design_bounds.h_F_max", 0), 0u) << rejection(s);
  EXPECT_NE(rejection(s).find("admissible"), std::string::npos) << rejection(s);
  s["design_bounds"] = {{"h_F_max", 0.2}, {"toe_within_height", false}};  // and P2's toe l_MT > h_F
  EXPECT_EQ(rejection(s), "accepted");
  s = design_spec();
  s["free_parameters"] = {"l_HM", "k_X"};
  EXPECT_EQ(rejection(s).rfind("free_parameters[1]", 0), 0u) << rejection(s);
  EXPECT_NE(rejection(s).find("l_MT"), std::string::npos) << rejection(s);  // the HMT parameters listed
  s["free_parameters"] = {"m_T"};  // a model parameter, but not the foot's
  EXPECT_EQ(rejection(s).rfind("free_parameters[0]", 0), 0u) << rejection(s);
  s = design_spec();
  s["foot"] = "P1-shoes-left-HM-SG";
  s["free_parameters"] = {"l_MT"};  // an HMT parameter the HM foot does not have
  EXPECT_EQ(rejection(s).rfind("free_parameters[0]", 0), 0u) << rejection(s);
  s = design_spec();
  s["design_speed"] = 2.25;
  EXPECT_EQ(rejection(s).rfind("design_speed", 0), 0u) << rejection(s);
  s["speeds"] = "1.0:0.25:2.5";
  EXPECT_EQ(rejection(s), "accepted");
  s = design_spec();
  s["foot"] = "point";
  EXPECT_EQ(rejection(s).rfind("foot", 0), 0u) << rejection(s);
  s = design_spec();
  s["start"] = {1.0};
  EXPECT_EQ(rejection(s).rfind("start", 0), 0u) << rejection(s);
  s = design_spec();
  s["foot_scale"] = 5;
  EXPECT_EQ(rejection(s).rfind("foot_scale", 0), 0u) << rejection(s);
  EXPECT_NE(rejection(s).find("3"), std::string::npos) << rejection(s);  // the admissible range
  s = design_spec();
  s["references"] = "yes";
  EXPECT_EQ(rejection(s).rfind("references", 0), 0u) << rejection(s);
}

// A design small enough for a unit test (tests/service/data/small_design.json): one density, two
// design starts at 2.3 m/s from the start foot (foot_scale 0), two speeds, P = 50, one start per
// sweep at one seed speed, correctors of at most 60 iterations and Delta_min = 0.05, so the
// free-foot continuation, which stalls near 2.28 m/s (section 10.2,
// bench/results/foot_design_bench.txt), gives up after a few tries. Whether a drawn start reaches a
// KKT point within MaxIter follows the build's rounding, so the spec also gives a design found
// before (known_designs, a KKT point): its start converges locally, and the job has a design on
// every host.
nlohmann::json small_design() {
  std::ifstream in(std::string(CYCLOPT_SOURCE_DIR) + "/tests/service/data/small_design.json");
  return nlohmann::json::parse(in);
}

std::map<int, std::vector<nlohmann::json>> by_curve(const std::vector<nlohmann::json>& rows) {
  std::map<int, std::vector<nlohmann::json>> curves;
  for (const auto& r : rows) curves[r["curve"].get<int>()].push_back(r);
  return curves;
}

class FootDesignJobs : public testing::MemqServerTest {
 protected:
  // Submits the small design to `srv` and returns its job id.
  std::int64_t submit(const std::string& id) {
    const auto ack = client_.submit(id, small_design().dump(), 5.0);
    EXPECT_TRUE(ack && ack->accepted) << (ack ? ack->problem : "no ack");
    return ack && ack->accepted ? ack->job_id : 0;
  }
  std::vector<nlohmann::json> rows(server::Server& srv, std::int64_t job) {
    storage::QueryRequest r = storage::query_for("solutions", job);
    r.limit = 1000;
    const storage::QueryPage page = storage::run_query(srv.store(), r);
    return {page.rows.begin(), page.rows.end()};
  }
};

TEST_F(FootDesignJobs, ASmallDesignStoresEveryPhaseAndTheDesignRecord) {
  const auto t0 = std::chrono::steady_clock::now();
  // Progress is published at most progress_hz times a second, a later report replacing a pending
  // one: at the default 5 Hz the design multistart's report could be replaced by the next step's
  // when both starts end together (seen under load). 100 Hz publishes the first start's report.
  config_.progress_hz = 100;
  server::Server srv(config_, kinds_, lcm_);
  const std::int64_t job = submit("design-1");
  ASSERT_GT(job, 0);
  std::set<std::string> steps;  // progress: the density and phase, and the design multistart's start
  int multistart_reports = 0;
  const auto done = client_.watch(job, [&](const cyclopt_lcm::job_progress_t& p) {
    steps.insert(p.message);
    if (p.phase.ends_with(": design multistart") && p.phase_total == 2 && p.phase_done >= 0) ++multistart_reports;
  }, 300.0);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->state, "done") << done->error;
  const std::vector<nlohmann::json> stored = rows(srv, job);
  std::printf("small foot_design job: %.1f s, %zu rows\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), stored.size());
  for (const std::string& s : steps) std::printf("  progress: %s\n", s.c_str());
  EXPECT_TRUE(steps.count("rho 10: free-foot continuation, the design's fixed-foot sweep beside it"))
      << "progress names the density and phase";
  EXPECT_GE(multistart_reports, 1) << "progress counts the design starts";
  auto curves = by_curve(stored);
  ASSERT_EQ(curves[records::kDesignCurve].size(), 1u);
  const nlohmann::json& row = curves[records::kDesignCurve][0];
  const auto design = row["values"].get<records::DesignedFootRecord>();
  std::printf("design record: %s\n", row["values"].dump().c_str());
  EXPECT_EQ(row["parameter"].get<double>(), 10.0);
  EXPECT_EQ(design.density, 10.0);
  EXPECT_EQ(design.starts, 2);
  ASSERT_TRUE(design.admissible) << design.reason.value_or("");
  EXPECT_EQ(row["status"], "ok");
  EXPECT_EQ(design.speeds, 2);
  // The references and the fixed-foot sweeps: one best point per speed, with the sweep's f_mech.
  for (const int c : {records::kStartFootCurve, records::kPointFeetCurve, records::high_design_curve(0),
                      records::low_design_curve(0)}) {
    ASSERT_EQ(curves[c].size(), 2u) << "curve " << c;
    for (const auto& r : curves[c]) {
      const auto s = r["values"].get<records::ComparedSpeedRecord>();
      EXPECT_EQ(r["status"], "converged") << "curve " << c << ": " << r.dump().substr(0, 300);
      EXPECT_DOUBLE_EQ(s.f_mech, r["values"]["gait"]["f_mech"].get<double>());
    }
  }
  // The multistart's optima: every class kept, the design marked, its foot the record's.
  const auto& optima = curves[records::design_multistart_curve(0)];
  ASSERT_GE(optima.size(), 1u);
  int designs = 0, admissible = 0;
  for (const auto& r : optima) {
    const auto p = r["values"].get<records::DesignPointRecord>();
    ASSERT_TRUE(p.design_class && p.class_reason);
    admissible += *p.design_class == "admissible";
    if (!p.design) continue;
    ++designs;
    EXPECT_EQ(r["point"].get<int>(), design.best);
    EXPECT_EQ(p.foot, design.design);
    EXPECT_EQ(p.active_bounds, design.active_bounds);
    EXPECT_DOUBLE_EQ(r["objective"].get<double>(), design.design_objective);
  }
  EXPECT_EQ(designs, 1);
  EXPECT_EQ(admissible, design.admissible_optima);
  EXPECT_EQ(static_cast<int>(optima.size()),
            design.admissible_optima + design.stilt_optima + design.wheel_optima + design.no_rolling_optima +
                design.under_resolved_optima);
  EXPECT_LE(design.design.parameters.at("h_F"), 0.1 + 1e-9);  // h_F,max of (10.1)
  EXPECT_GT(design.design.m_F, 0.0);
  // The free-foot continuation starts at the design.
  const auto& free_foot = curves[records::free_foot_curve(0)];
  ASSERT_GE(free_foot.size(), 1u);
  EXPECT_DOUBLE_EQ(free_foot.front()["parameter"].get<double>(), 2.3);
  EXPECT_EQ(free_foot.front()["values"].get<records::DesignPointRecord>().foot.parameters, design.design.parameters);
  EXPECT_GE(design.free_foot_speeds, 1);
  // Mean f_mech and savings from the stored sweeps.
  double high = 0, low = 0, start = 0, point = 0;
  for (int i = 0; i < 2; ++i) {
    high += curves[records::high_design_curve(0)][i]["values"]["f_mech"].get<double>() / 2;
    low += curves[records::low_design_curve(0)][i]["values"]["f_mech"].get<double>() / 2;
    start += curves[records::kStartFootCurve][i]["values"]["f_mech"].get<double>() / 2;
    point += curves[records::kPointFeetCurve][i]["values"]["f_mech"].get<double>() / 2;
  }
  EXPECT_EQ(design.speeds_reached, 2);
  EXPECT_NEAR(design.mean_f_mech, high, 1e-12);
  EXPECT_NEAR(design.saving_vs_start, 1 - high / start, 1e-12);
  EXPECT_NEAR(design.saving_vs_point, 1 - high / point, 1e-12);
  EXPECT_EQ(design.low_speeds_reached, 2);
  EXPECT_NEAR(design.low_mean_f_mech, low, 1e-12);
  EXPECT_NEAR(design.low_saving_vs_point, 1 - low / point, 1e-12);
  EXPECT_EQ(design.answer, low < high ? "low-speed design" : "design");  // both reached both speeds
  std::printf("rho 10: design f %.5f at 2.3 m/s, mean f_mech %.5f (start foot %.5f, point feet %.5f), savings %.1f %% / %.1f %%\n",
              design.design_objective, high, start, point, 100 * design.saving_vs_start, 100 * design.saving_vs_point);

  // `cyclopt plot foot-design` and `cyclopt report` of the job, from the document `cyclopt export` writes.
  nlohmann::json doc = storage::run_query(srv.store(), storage::query_for("job", job)).rows.at(0);
  for (const char* what : storage::kJobParts) {
    storage::QueryRequest r = storage::query_for(what, job);
    r.limit = 1000;
    doc[what] = storage::run_query(srv.store(), r).rows;
  }
  std::vector<std::string> not_drawn;
  const std::vector<plot::Figure> figures = plot::foot_design_figures(doc, &not_drawn);
  for (const std::string& why : not_drawn) std::printf("  not drawn: %s\n", why.c_str());
  ASSERT_EQ(figures.size(), 3u);
  EXPECT_EQ(figures[0].name, "foot_design_outlines");
  EXPECT_EQ(figures[1].name, "foot_design_cost");
  EXPECT_EQ(figures[2].name, "foot_design_gait");
  const auto& chart = std::get<plot::LineChart>(figures[1].drawing);
  ASSERT_EQ(chart.series.size(), 4u);  // start foot, point feet, the rho 10 design and low-speed design
  for (int k : {0, 1}) {
    const int curve = k == 0 ? records::high_design_curve(0) : records::low_design_curve(0);
    EXPECT_EQ(chart.series[2 + k].y, (std::vector<double>{curves[curve][0]["values"]["f_mech"].get<double>(),
                                                          curves[curve][1]["values"]["f_mech"].get<double>()}));
    EXPECT_EQ(chart.series[2 + k].dashed, k == 1);
  }
  const std::string html = plot::to_html(plot::foot_design_report(doc));
  EXPECT_NE(html.find("Designs per density"), std::string::npos);
  EXPECT_NE(html.find("best design"), std::string::npos);
  EXPECT_NE(html.find("Best: the " + design.answer + " of ρ = 10"), std::string::npos);
  EXPECT_NE(html.find("low-speed design ("), std::string::npos);  // its row in the table of designs
  // CYCLOPT_TEST_FIGURE_DIR keeps the pictures and the report, to look at them.
  const std::string keep = std::getenv("CYCLOPT_TEST_FIGURE_DIR") ? std::getenv("CYCLOPT_TEST_FIGURE_DIR") : "";
  const std::string out = keep.empty() ? (dir_ / "figures").string() : keep;
  for (const plot::Figure& f : figures)
    for (const std::string& path : plot::write_figure(f, out)) EXPECT_GT(std::filesystem::file_size(path), 1000u) << path;
  plot::write_html(plot::foot_design_report(doc), out + "/report.html");
}

// Issue 15 item 3: an interrupted study resumes without recomputing stored work. The server is
// stopped once the references are stored (in the design multistart); the second attempt replays
// the reference sweeps (work units start-foot and point-feet, whose results are checkpoints too) and
// the finished design solves from the checkpoints: every checkpoint of
// the first attempt is unchanged (a solve done again records its own wall time), every point of
// the first attempt keeps its solved_at, and the job ends as an uninterrupted one.
TEST_F(FootDesignJobs, AnInterruptedDesignResumesWithoutSolvingAgain) {
  std::int64_t job = 0;
  {
    server::Server srv(config_, kinds_, lcm_);
    job = submit("design-resume");
    ASSERT_GT(job, 0);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (srv.store().job(job)->points_stored < 4 && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }  // graceful stop: the job goes back to the queue
  std::map<std::string, std::string> checkpoints;
  std::map<std::pair<int, int>, double> solved_at;
  {
    storage::ResultStore s(config_.database);
    EXPECT_EQ(s.job(job)->state, storage::JobState::queued);
    checkpoints = s.checkpoints(job);
    storage::QueryRequest r = storage::query_for("solutions", job);
    r.limit = 1000;
    for (const nlohmann::json& row : storage::run_query(s, r).rows)
      solved_at[{row["curve"].get<int>(), row["point"].get<int>()}] = row["solved_at"].get<double>();
  }
  ASSERT_GE(solved_at.size(), 4u);
  EXPECT_GE(checkpoints.size(), 2u);  // at least the reference sweeps' solves and runs
  const auto t0 = std::chrono::steady_clock::now();
  server::Server srv(config_, kinds_, lcm_);
  const auto done = client_.watch(job, [](const auto&) {}, 120.0);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->state, "done") << done->error;
  EXPECT_EQ(srv.store().job(job)->attempts, 2);
  const std::map<std::string, std::string> after = srv.store().checkpoints(job);
  int references = 0;
  for (const auto& [key, value] : checkpoints) {
    ASSERT_TRUE(after.count(key)) << key;
    EXPECT_EQ(after.at(key), value) << key << " was solved again";
    references += key.rfind("unit/start-foot/", 0) == 0 || key.rfind("unit/point-feet/", 0) == 0;  // work units
  }
  EXPECT_GT(references, 0);
  EXPECT_GT(after.size(), checkpoints.size());  // the rest was solved in the second attempt
  int kept = 0;
  for (const nlohmann::json& row : rows(srv, job)) {
    const auto it = solved_at.find({row["curve"].get<int>(), row["point"].get<int>()});
    if (it == solved_at.end()) continue;
    EXPECT_EQ(row["solved_at"].get<double>(), it->second) << row.dump().substr(0, 200);
    ++kept;
  }
  EXPECT_EQ(kept, static_cast<int>(solved_at.size()));
  std::printf("resumed after %zu points and %zu checkpoints (%d of the references); second attempt %.1f s, %zu checkpoints in all\n",
              solved_at.size(), checkpoints.size(), references,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), after.size());
}

}  // namespace
}  // namespace cyclopt
