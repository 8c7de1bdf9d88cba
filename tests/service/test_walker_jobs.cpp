// The walker job kinds through the server over memq:// (walker_job_kinds.hpp,
// walker_continuation_kinds.hpp): evaluate, optimise, continuation and sweep store real gaits with their solver summaries and trajectories; bad walker fields are
// rejected naming the field and its range.
#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt_channels.hpp"
#include "memq_server_fixture.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace cyclopt {
namespace {

nlohmann::json walker_spec(const std::string& task) {
  return {{"scene", "walker"}, {"task", task}, {"foot", "point"}, {"speed", 1.0},
          {"solver", {{"max_iterations", 600}}}};
}

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

TEST(WalkerJobSpec, RejectsBadWalkerFieldsNamingThem) {
  const service::JobKindRegistry kinds = service::builtin_job_kinds();
  auto rejection = [&](nlohmann::json spec) -> std::string {
    try {
      service::validate_job_spec(spec, kinds);
    } catch (const service::SpecError& e) {
      return e.field() + ": " + e.what();
    }
    return "accepted";
  };
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
