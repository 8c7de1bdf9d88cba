// The walker job kinds through the server over memq:// (walker_job_kinds.hpp,
// walker_continuation_kinds.hpp): evaluate, optimise, continuation and sweep store real gaits with their solver summaries and trajectories; bad walker fields are
// rejected naming the field and its range.
#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt_channels.hpp"
#include "memq_server_fixture.hpp"
#include "spec_rejection.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace cyclopt {
namespace {

nlohmann::json walker_spec(const std::string& task) {
  return {{"scene", "walker"}, {"task", task}, {"foot", "point"}, {"speed", 1.0},
          {"solver", {{"max_iterations", 600}}}};
}

using testing::rejection;
using WalkerJobs = testing::MemqServerTest;

TEST_F(WalkerJobs, EvaluateStoresTheStartingGait) {
  const auto rows = run_job("eval-1", walker_spec("evaluate"), 1);
  ASSERT_EQ(rows.size(), 1u);
  std::printf("evaluate row: %s\n", rows[0].dump().substr(0, 300).c_str());
  const nlohmann::json values = rows[0]["values"];
  EXPECT_TRUE(values["gait"]["real"].get<bool>());
  EXPECT_NEAR(values["gait"]["mean_speed"].get<double>(), 1.0, 1e-8);
  EXPECT_EQ(values["x"].size(), 20u);  // point feet: (M - 1) n_b = 5 x 4
}

// Issue 17 item 5: what `cyclopt export`, `plot` and `report` fetch (the job row and every part)
// arrives through the server whole, although a walker trajectory row exceeds one reply.
TEST_F(WalkerJobs, ExportThroughTheServerCarriesRowsLargerThanOneReply) {
  server::Server srv(config_, kinds_, lcm_);
  const auto ack = client_.submit("export-1", walker_spec("evaluate").dump(), 5.0);
  ASSERT_TRUE(ack && ack->accepted);
  const auto done = client_.watch(ack->job_id, [](const cyclopt_lcm::job_progress_t&) {}, 120.0);
  ASSERT_TRUE(done);
  ASSERT_EQ(done->state, "done") << done->error;
  std::size_t largest = 0;
  for (const std::string what : {"job", "events", "curves", "solutions", "trajectories"}) {
    storage::QueryRequest r = storage::query_for(what, ack->job_id);
    r.limit = 1000;
    const auto remote = client_.query(r, 10.0);
    ASSERT_TRUE(remote) << what;
    const storage::QueryPage local = storage::run_query(srv.store(), r);
    EXPECT_EQ(remote->total, local.total) << what;
    ASSERT_EQ(remote->rows.size(), local.rows.size()) << what;
    for (std::size_t i = 0; i < local.rows.size(); ++i) {
      EXPECT_EQ(remote->rows[i], local.rows[i]) << what << " row " << i;
      largest = std::max(largest, local.rows[i].dump().size());
    }
  }
  std::printf("largest row through the server: %zu bytes (one reply carries %zu)\n", largest,
              channels::kMaxQueryReplyRowBytes);
  EXPECT_GT(largest, channels::kMaxQueryReplyRowBytes);
}

TEST_F(WalkerJobs, OptimiseLowersTheCostOfTransport) {
  const auto rows = run_job("opt-1", walker_spec("optimise"), 1);
  ASSERT_EQ(rows.size(), 1u);
  const nlohmann::json values = rows[0]["values"];
  const double start = values["start_objective"].get<double>(), end = values["gait"]["objective"].get<double>();
  std::printf("optimise: f_mech %.5f -> %.5f, %s after %d iterations\n", start, end,
              values["solver"]["termination"].get<std::string>().c_str(), values["solver"]["iterations"].get<int>());
  EXPECT_LT(end, start);
  EXPECT_TRUE(values["gait"]["real"].get<bool>());
  EXPECT_TRUE(values["solver"]["success"].get<bool>());
}

// Issue 17 item 2: a job whose only solve ended at max_iterations is not "done": it fails, keeps
// the point, and says which point did not converge and why.
TEST_F(WalkerJobs, AJobWhoseSolveDidNotConvergeFailsNamingThePoint) {
  server::Server srv(config_, kinds_, lcm_);
  nlohmann::json spec = walker_spec("optimise");
  spec["solver"]["max_iterations"] = 2;
  const auto ack = client_.submit("unconverged-1", spec.dump(), 5.0);
  ASSERT_TRUE(ack && ack->accepted) << (ack ? ack->problem : "no ack");
  const auto done = client_.watch(ack->job_id, [](const cyclopt_lcm::job_progress_t&) {}, 120.0);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->state, "failed");
  EXPECT_EQ(done->points_stored, 1);
  EXPECT_EQ(done->points_expected, 1);
  EXPECT_EQ(done->points_converged, 0);
  EXPECT_EQ(done->error, "0 of 1 points converged; not converged: speed 1 (max_iterations)");
  const storage::QueryPage job = storage::run_query(srv.store(), storage::query_for("job", ack->job_id));
  EXPECT_EQ(job.rows.at(0)["state"], "failed");
  EXPECT_EQ(job.rows.at(0)["points_converged"], 0);
}

TEST_F(WalkerJobs, ContinuationStoresEveryPointWithItsCurve) {
  nlohmann::json spec = walker_spec("continuation");
  spec.erase("speed");
  spec["speeds"] = "1.0:0.1:1.2";
  const auto rows = run_job("cont-1", spec, -1);
  ASSERT_GE(rows.size(), 3u);
  int on_grid = 0;
  for (const auto& r : rows) {
    const nlohmann::json values = r["values"];
    std::printf("continuation v = %.3f: curve %d, f_mech %.5f, %s, %d iterations, predictor %d/%d\n",
                r["parameter"].get<double>(), values["curve_id"].get<int>(), values["gait"]["objective"].get<double>(),
                values["solver"]["termination"].get<std::string>().c_str(), values["solver"]["iterations"].get<int>(),
                values["predictor_attempts"].get<int>(), values["predictor_steps"].get<int>());
    EXPECT_EQ(r["curve"].get<int>(), values["curve_id"].get<int>());
    EXPECT_TRUE(values["gait"]["real"].get<bool>());
    EXPECT_NEAR(values["gait"]["mean_speed"].get<double>(), r["parameter"].get<double>(), 1e-8);
    on_grid += values["on_grid"].get<bool>();
  }
  EXPECT_EQ(on_grid, 3);
}

TEST_F(WalkerJobs, SweepSelectsTheBestPointPerSpeed) {
  nlohmann::json spec = walker_spec("sweep");
  spec.erase("speed");
  spec["speeds"] = "0.9:0.1:1.1";
  spec["multistart"] = {{"starts", 2}, {"seed", 3}, {"scale", 0.02}};
  spec["continuation"] = {{"seed_speeds", 1.0}};
  const auto rows = run_job("sweep-1", spec, -1);
  int best = 0;
  for (const auto& r : rows) {
    if (r["curve"].get<int>() != 0) continue;
    ++best;
    const nlohmann::json values = r["values"];
    std::printf("sweep best v = %.1f: curve %d, f_mech %.5f (%s)\n", r["parameter"].get<double>(),
                values["curve_id"].get<int>(), values["gait"]["objective"].get<double>(),
                values["solver"]["termination"].get<std::string>().c_str());
    EXPECT_TRUE(values["gait"]["real"].get<bool>());
    EXPECT_NEAR(values["gait"]["mean_speed"].get<double>(), r["parameter"].get<double>(), 1e-8);
  }
  EXPECT_EQ(best, 3);
}

// foot_comparison (foot_comparison_kind.hpp): point feet against one rolling foot at two speeds.
// Curve 0 holds the better foot per speed, curves 1-2 each foot's best points, curve 3 the summary,
// whose mean f_mech and saving must follow from the stored per-speed gaits.
TEST_F(WalkerJobs, FootComparisonStoresEveryFootTheEnvelopeAndTheSavings) {
  const nlohmann::json spec = {{"scene", "walker"},
                               {"task", "foot_comparison"},
                               {"speeds", "1.0:0.1:1.1"},
                               {"points", 50},
                               {"feet", {"P1-shoes-left-HM-SG"}},
                               {"multistart", {{"starts", 2}, {"seed", 3}, {"scale", 0.02}}},
                               {"continuation", {{"seed_speeds", 1.0}}}};
  const auto rows = run_job("comparison-1", spec, 2 * 2 + 2 + 2);
  std::map<int, std::vector<nlohmann::json>> by_curve;
  for (const auto& r : rows) by_curve[r["curve"].get<int>()].push_back(r);
  ASSERT_EQ(by_curve[1].size(), 2u);
  ASSERT_EQ(by_curve[2].size(), 2u);
  ASSERT_EQ(by_curve[3].size(), 2u);
  double sum[2] = {0, 0};
  for (int k = 0; k < 2; ++k)
    for (const auto& r : by_curve[1 + k]) {
      const nlohmann::json& v = r["values"];
      ASSERT_TRUE(v.contains("f_mech")) << r.dump().substr(0, 400);
      // The stored f_mech is the gait's own (values.gait), at the requested speed.
      EXPECT_DOUBLE_EQ(v["f_mech"].get<double>(), v["gait"]["f_mech"].get<double>());
      EXPECT_NEAR(v["gait"]["mean_speed"].get<double>(), r["parameter"].get<double>(), 1e-8);
      sum[k] += v["f_mech"].get<double>();
    }
  for (const auto& r : by_curve[0]) {
    EXPECT_EQ(r["values"]["foot"], "P1-shoes-left-HM-SG");  // the only compared foot
    EXPECT_NEAR(r["values"]["saving"].get<double>(),
                1.0 - r["values"]["f_mech"].get<double>() / r["values"]["reference_f_mech"].get<double>(), 1e-12);
  }
  const nlohmann::json& point = by_curve[3][0]["values"];
  const nlohmann::json& rolling = by_curve[3][1]["values"];
  EXPECT_EQ(point["foot"], "point");
  EXPECT_TRUE(point["reference"].get<bool>());
  EXPECT_TRUE(rolling["best_fitted"].get<bool>());
  EXPECT_EQ(rolling["common_speeds"].get<int>(), 2);
  EXPECT_NEAR(rolling["mean_f_mech"].get<double>(), sum[1] / 2, 1e-12);
  EXPECT_NEAR(rolling["saving"].get<double>(), 1.0 - sum[1] / sum[0], 1e-12);
  std::printf("foot_comparison: point %.5f, P1 shoes HM %.5f, saving %.1f %%\n", sum[0] / 2, sum[1] / 2,
              100 * rolling["saving"].get<double>());

  // A compared foot's gait starts a gait job (stored_start.hpp): curve 2 holds the first compared
  // foot's gaits; started at that optimum, the solve ends at a KKT point with the same f_mech.
  nlohmann::json again = {{"scene", "walker"}, {"task", "optimise"}, {"foot", "P1-shoes-left-HM-SG"},
                          {"speed", 1.0}, {"points", 50}, {"start", {{"job", 1}, {"curve", 2}, {"point", 0}}}};
  const auto gait = run_job("comparison-gait", again, 1);
  ASSERT_EQ(gait.size(), 1u);
  EXPECT_EQ(gait[0]["status"], "converged");
  const double stored = by_curve[2][0]["values"]["f_mech"].get<double>();
  EXPECT_NEAR(gait[0]["values"]["gait"]["f_mech"].get<double>(), stored, 1e-6 * stored);
  // The summary curve holds no gaits, and the reference's gaits are point feet's.
  server::Server srv(config_, kinds_, lcm_);
  again["start"]["curve"] = 3;
  const auto summary = client_.submit("comparison-summary", again.dump(), 5.0);
  ASSERT_TRUE(summary);
  EXPECT_FALSE(summary->accepted);
  EXPECT_EQ(summary->field, "start.curve") << summary->problem;
  again["start"]["curve"] = 1;
  const auto reference = client_.submit("comparison-reference", again.dump(), 5.0);
  ASSERT_TRUE(reference);
  EXPECT_FALSE(reference->accepted);
  EXPECT_EQ(reference->field, "start.job") << reference->problem;  // point feet, not HM
}

TEST(WalkerJobSpec, FootComparisonRejectsBadFeetNamingThem) {
  const nlohmann::json good = {{"scene", "walker"}, {"task", "foot_comparison"}, {"speeds", "0.3:0.1:2.3"}};
  EXPECT_EQ(rejection(good), "accepted");  // the 16 feet of section 9.2 against point feet
  nlohmann::json s = good;
  s["feet"] = {"P1-shoes-left-HM-SG", "P9-barefoot-left-XX"};
  EXPECT_EQ(rejection(s).rfind("feet[1]", 0), 0u) << rejection(s);
  s = good;
  s["feet"] = {"P2-shoes-left-HMT", "P2-shoes-left-HMT"};
  EXPECT_NE(rejection(s).find("compared twice"), std::string::npos) << rejection(s);
  s = good;
  s["foot"] = "point";
  EXPECT_EQ(rejection(s).rfind("foot", 0), 0u) << rejection(s);
  s = good;
  s["reference"] = "nowhere";
  EXPECT_EQ(rejection(s).rfind("reference", 0), 0u) << rejection(s);
  s = good;
  s["feet"] = nlohmann::json::array();
  EXPECT_EQ(rejection(s).rfind("feet", 0), 0u) << rejection(s);
}

// continuation.<field> for every kind that sweeps: the `good` values accepted, the `bad` ones refused
// naming the field and `bound` (the admissible range's end).
void expect_sweep_continuation_field(const std::string& field, const std::vector<nlohmann::json>& good,
                                     const std::vector<nlohmann::json>& bad, const std::string& bound) {
  const nlohmann::json sweep = {{"scene", "walker"}, {"task", "sweep"}, {"foot", "point"}, {"speeds", "0.6:0.1:0.8"}};
  const nlohmann::json comparison = {{"scene", "walker"}, {"task", "foot_comparison"}, {"speeds", "0.3:0.1:2.3"}};
  for (const nlohmann::json& spec : {sweep, comparison}) {
    nlohmann::json s = spec;
    for (const nlohmann::json& v : good) {
      s["continuation"] = {{field, v}};
      EXPECT_EQ(rejection(s), "accepted") << field << " " << v;
    }
    for (const nlohmann::json& v : bad) {
      s["continuation"] = {{field, v}};
      const std::string refused = rejection(s);
      EXPECT_EQ(refused.rfind("continuation." + field + ": ", 0), 0u) << refused;
      EXPECT_NE(refused.find(bound), std::string::npos) << refused;
    }
  }
}

TEST(WalkerJobSpec, CoarseMultistartGridIsOffOrAUsableGrid) {
  // continuation.coarse_points: 0 (off) or [25, 20000] like points.
  expect_sweep_continuation_field("coarse_points", {0, 25, 100}, {-1, 1, 24, 20001}, "20000");
}

TEST(WalkerJobSpec, RunnerUpsAreACountUpToTen) {
  // continuation.runner_ups: further seed-speed optima continued while they are the best known.
  expect_sweep_continuation_field("runner_ups", {0, 2, 10}, {-1, 11, 1.5, "2"}, "10");
}

TEST(WalkerJobSpec, PredictorHessianIsPerPointOrPerTry) {
  for (const char* task : {"sweep", "continuation"}) {
    nlohmann::json s = {{"scene", "walker"}, {"task", task}, {"foot", "point"}, {"speeds", "0.6:0.1:0.8"}};
    for (const char* good : {"per_point", "per_try"}) {
      s["continuation"] = {{"predictor_hessian", good}};
      EXPECT_EQ(rejection(s), "accepted") << task << " " << good;
    }
    s["continuation"] = {{"predictor_hessian", "sometimes"}};
    EXPECT_EQ(rejection(s).rfind("continuation.predictor_hessian: ", 0), 0u) << rejection(s);
    EXPECT_NE(rejection(s).find("per_try"), std::string::npos) << rejection(s);
  }
}

TEST(WalkerJobSpec, RejectsBadWalkerFieldsNamingThem) {
  nlohmann::json s = walker_spec("optimise");
  s["speed"] = 7.0;
  EXPECT_NE(rejection(s).find("speed"), std::string::npos) << rejection(s);
  s = walker_spec("optimise");
  s["free_parameters"] = {"l_HM"};  // point feet have no foot geometry
  EXPECT_NE(rejection(s).find("free_parameters[0]"), std::string::npos) << rejection(s);
  s = walker_spec("optimise");
  s["start"] = {1.0, 2.0};
  EXPECT_NE(rejection(s).find("start"), std::string::npos) << rejection(s);
  s = walker_spec("sweep");
  EXPECT_NE(rejection(s).find("speeds"), std::string::npos) << rejection(s);
  s = walker_spec("optimise");
  s["objective"] = "happiness";
  EXPECT_NE(rejection(s).find("f_mech"), std::string::npos) << rejection(s);
  EXPECT_EQ(rejection(walker_spec("optimise")), "accepted");
}

}  // namespace
}  // namespace cyclopt
