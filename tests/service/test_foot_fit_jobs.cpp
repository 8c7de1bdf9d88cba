// The foot_fit job kind through the server over memq:// (service/foot_fit_kind.hpp, issue 20
// item 3): synthetic trials of a catalogue foot, submitted as their ankle tracks, come back as
// the HM and HMT fit records; malformed trials are rejected at submission naming the element.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot_fit/synthetic_trials.hpp"
#include "cyclopt/io/foot_fit_json.hpp"
#include "cyclopt/plot/foot_fit_figures.hpp"
#include "cyclopt/records/foot_fit_record.hpp"
#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/storage_read/result_queries.hpp"
#include "cyclopt_channels.hpp"
#include "memq_server_fixture.hpp"
#include "spec_rejection.hpp"
#include "point_table.hpp"

#include <gtest/gtest.h>

namespace cyclopt {
namespace {

namespace ff = foot_fit;
using testing::rejection;

// Three trials of `preset` at 200 Hz with `noise` per marker coordinate, as cyclopt-foot synth
// writes them, reduced to their ankle tracks.
std::vector<ff::AnkleTrack> synthetic_tracks(const std::string& preset, double noise) {
  const foot::FootSpec spec = foot::foot_preset(preset).spec;
  std::vector<ff::AnkleTrack> tracks;
  for (int k = 0; k < 3; ++k) {
    ff::SyntheticTrialOptions o;
    o.noise = noise;
    o.offset = 0.4 + 0.11 * k;
    o.walking_direction = 0.02 * k;
    o.seed = 1 + k;
    o.foot_angle = ff::default_foot_angle_history(spec);
    for (ff::FootAngleKnot& knot : o.foot_angle) knot.t *= 1.0 + 0.07 * k;
    o.source = "trial" + std::to_string(k + 1);
    tracks.push_back(ff::ankle_track(ff::synthetic_trial(spec, o)));
  }
  return tracks;
}

using FootFitJobs = testing::MemqServerTest;

TEST_F(FootFitJobs, StoresTheHmAndHmtFitsOfTheTrials) {
  const nlohmann::json spec = io::foot_fit_job_spec(synthetic_tracks("P1-shoes-left-HMT", 0.0005));
  std::printf("foot_fit spec: %zu bytes for %zu samples\n", spec.dump().size(),
              3 * spec["trials"][0]["x"].size());
  ASSERT_LE(spec.dump().size(), channels::kMaxSpecBytes);
  const auto rows = run_job("fit-1", spec, 2);
  ASSERT_EQ(rows.size(), 2u);
  const auto hm = rows[0]["values"].get<records::FootFitRecord>();
  const auto hmt = rows[1]["values"].get<records::FootFitRecord>();
  EXPECT_EQ(hm.model, "HM");
  EXPECT_EQ(hmt.model, "HMT");
  EXPECT_TRUE(hm.converged) << hm.message;
  EXPECT_TRUE(hmt.converged) << hmt.message;
  EXPECT_EQ(rows[1]["status"], "converged");
  EXPECT_LE(hmt.rms, hm.rms);  // seed 001 section 4.3
  // 0.5 mm per marker coordinate, the ankle the mean of two: 0.35 mm per coordinate, 0.5 mm in 2-D.
  EXPECT_GT(hmt.rms, 0.3e-3);
  EXPECT_LT(hmt.rms, 0.7e-3);
  ASSERT_EQ(hmt.trials.size(), 3u);
  EXPECT_EQ(hmt.trials[2].source, "trial3");
  EXPECT_EQ(hmt.parameters.size(), 9u);
  EXPECT_FALSE(hmt.convexity.empty());
  EXPECT_TRUE(hmt.convex);
  const double l_HM_true = foot::foot_preset("P1-shoes-left-HMT").spec.parameters[foot::hmt::l_HM];
  for (const records::FittedParameterRecord& p : hmt.parameters)
    if (p.name == "l_HM") {
      EXPECT_NEAR(p.value, l_HM_true, 5 * p.standard_error + 1e-4);
    }
  EXPECT_EQ(hmt.foot["model"], "HMT");
  const auto summary = client::point_summary(rows[1]);  // `cyclopt query` reads the same record
  ASSERT_TRUE(summary);
  EXPECT_EQ((*summary)["model"], "HMT");
  EXPECT_EQ((*summary)["l_MT"], hmt.parameters[foot::hmt::l_MT].value);
  EXPECT_FALSE(summary->contains("k_H"));  // fixed by the seed's bounds
  EXPECT_EQ(nlohmann::json(rows[1]["values"].get<records::FootFitRecord>()), rows[1]["values"]);  // the record round-trips (NaN != NaN: compare JSON)
}

// Issue 20 item 3: the stored fit as the foot of a walker job, by reference (stored_foot_fit.hpp).
TEST_F(FootFitJobs, AnOptimiseJobWalksOnTheStoredFit) {
  server::Server srv(config_, kinds_, lcm_);
  auto finished = [&](const std::string& id, const nlohmann::json& spec) -> std::int64_t {
    const auto ack = client_.submit(id, spec.dump(), 5.0);
    EXPECT_TRUE(ack && ack->accepted) << (ack ? ack->problem : "no ack");
    if (!ack || !ack->accepted) return 0;
    const auto done = client_.watch(ack->job_id, [](const cyclopt_lcm::job_progress_t&) {}, 300.0);
    EXPECT_TRUE(done && done->state == "done") << (done ? done->error : "no done message");
    return ack->job_id;
  };
  auto problem = [&](const std::string& id, const nlohmann::json& spec) {
    const auto ack = client_.submit(id, spec.dump(), 5.0);
    return !ack ? std::string("no ack") : ack->accepted ? std::string("accepted") : ack->problem;
  };
  const std::int64_t fit = finished("fit-2", io::foot_fit_job_spec(synthetic_tracks("P1-shoes-left-HMT", 0.0005)));
  ASSERT_GT(fit, 0);
  {  // `cyclopt plot foot-fit --job` draws the stored fits from the document `cyclopt export` writes
    nlohmann::json doc = storage::run_query(srv.store(), storage::query_for("job", fit)).rows.at(0);
    for (const char* what : storage::kJobParts) doc[what] = storage::run_query(srv.store(), storage::query_for(what, fit)).rows;
    std::vector<std::string> not_drawn;
    const std::vector<plot::Figure> figures = plot::foot_fit_job_figures(doc, &not_drawn);
    EXPECT_TRUE(not_drawn.empty()) << not_drawn.front();
    ASSERT_EQ(figures.size(), 4u);
    EXPECT_EQ(figures[0].name, "fit_hm_ankle");
    EXPECT_EQ(figures[3].name, "fit_hmt_outline");
    for (const plot::Figure& f : figures)
      for (const std::string& path : plot::write_figure(f, (dir_ / "figures").string()))
        EXPECT_GT(std::filesystem::file_size(path), 1000u) << path;
  }
  nlohmann::json walk = {{"scene", "walker"}, {"task", "optimise"}, {"speed", 1.3},
                         {"foot", {{"fit", {{"job", fit}, {"model", "HMT"}}}}}};
  const std::int64_t job = finished("walk-1", walk);
  ASSERT_GT(job, 0);
  const storage::JobRecord stored = *srv.store().job(job);
  const nlohmann::json resolved = nlohmann::json::parse(stored.resolved_spec_json);
  const auto hmt = nlohmann::json::parse(*srv.store().point_values(fit, {0, 1})).get<records::FootFitRecord>();
  EXPECT_EQ(resolved["foot"]["model"], "HMT");
  EXPECT_EQ(resolved["foot"]["l_HM"], hmt.foot["l_HM"]);  // the fitted foot, not a preset
  EXPECT_EQ(resolved["foot"]["name"], "fitted HMT (job " + std::to_string(fit) + ")");
  EXPECT_EQ(nlohmann::json::parse(stored.spec_json)["foot"], walk["foot"]);  // stored as submitted
  const storage::QueryPage rows = storage::run_query(srv.store(), storage::query_for("solutions", job));
  ASSERT_EQ(rows.rows.size(), 1u);
  EXPECT_EQ(rows.rows[0]["status"], "converged");
  std::printf("optimise on the fitted HMT foot: f_mech %.5f\n", rows.rows[0]["objective"].get<double>());

  // What the reference may not name, each under its field.
  walk["foot"] = {{"fit", {{"job", 999}}}};
  EXPECT_EQ(problem("walk-2", walk), "foot.fit.job: there is no job 999 in this server's database");
  walk["foot"] = {{"fit", {{"job", job}}}};
  EXPECT_EQ(problem("walk-3", walk), "foot.fit.job: job " + std::to_string(job) + " is a walker optimise job, not a foot_fit job");
  walk["foot"] = {{"fit", {{"job", fit}, {"model", "HMTT"}}}};
  EXPECT_EQ(problem("walk-4", walk).rfind("foot.fit.model:", 0), 0u);
  walk["foot"] = {{"fit", {{"job", fit}}}};
  walk["foot"]["density"] = 30;
  EXPECT_EQ(problem("walk-5", walk), "foot.density: unknown field (admissible: fit)");
}

TEST(FootFitSpec, MalformedTrialsAreRejectedNamingTheElement) {
  nlohmann::json spec = io::foot_fit_job_spec(synthetic_tracks("P1-shoes-left-HM-SG", 0.0));
  EXPECT_EQ(rejection(spec), "accepted");
  nlohmann::json bad = spec;
  bad["trials"][1]["z"][17] = "nan";
  EXPECT_EQ(rejection(bad).rfind("trials[1].z[17]: must be a number in [-100, 100] m, got \"nan\"", 0), 0u) << rejection(bad);
  bad = spec;
  bad["trials"][0]["x"].erase(3);
  EXPECT_EQ(rejection(bad).rfind("trials[0].z: has", 0), 0u) << rejection(bad);
  bad = spec;
  bad["trials"][2]["y"] = {1.0};
  EXPECT_EQ(rejection(bad).rfind("trials[2].y: is not a field", 0), 0u) << rejection(bad);
  bad = spec;
  bad["trials"] = nlohmann::json::array();
  EXPECT_EQ(rejection(bad).rfind("trials: must be an array of 1 to 100", 0), 0u) << rejection(bad);
  // Only the forefoot half of each trial: the circle-fit start (4.10) has no heel points.
  bad = spec;
  for (nlohmann::json& t : bad["trials"]) {
    const std::size_t n = t["x"].size();
    for (const char* c : {"x", "z"}) {
      std::vector<double> v = t[c].get<std::vector<double>>();
      const std::size_t lowest = std::min_element(t["z"].begin(), t["z"].end(),
                                                  [](const auto& a, const auto& b) { return a.template get<double>() < b.template get<double>(); }) -
                                 t["z"].begin();
      t[c] = std::vector<double>(v.begin() + static_cast<long>(lowest), v.begin() + static_cast<long>(n));
    }
  }
  EXPECT_EQ(rejection(bad).rfind("trials: circle fit (eq. 4.10)", 0), 0u) << rejection(bad);
  bad = spec;
  bad["toe_bound"] = "yes";
  EXPECT_EQ(rejection(bad), "toe_bound: must be true or false");
}

}  // namespace
}  // namespace cyclopt
