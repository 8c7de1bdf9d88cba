// The walker job kinds through the server over memq:// (walker_job_kinds.hpp): evaluate, optimise
// and sweep store real gaits with their solver summaries and trajectories; bad walker fields are
// rejected naming the field and its range.
#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "memq_server_fixture.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace cyclopt {
namespace {

nlohmann::json walker_spec(const std::string& task) {
  return {{"scene", "walker"}, {"task", task}, {"foot", "point"}, {"speed", 1.0},
          {"solver", {{"max_iterations", 600}}}};
}

class WalkerJobs : public testing::MemqServerTest {
 protected:
  // Submits, waits for completion and returns the stored solution rows.
  std::vector<nlohmann::json> run(const std::string& id, const nlohmann::json& spec, int expected_points) {
    server::Server srv(config_, kinds_, lcm_);
    const auto ack = client_.submit(id, spec.dump(), 5.0);
    EXPECT_TRUE(ack && ack->accepted) << (ack ? ack->problem : "no ack");
    if (!ack || !ack->accepted) return {};
    const auto done = client_.watch(ack->job_id, [](const cyclopt_lcm::job_progress_t&) {}, 120.0);
    EXPECT_TRUE(done);
    if (!done) return {};
    EXPECT_EQ(done->state, "done") << done->error;
    EXPECT_EQ(done->points_stored, expected_points);
    const auto page = client_.query(storage::query_for("solutions", ack->job_id), 5.0);
    EXPECT_TRUE(page);
    std::vector<nlohmann::json> rows;
    if (page)
      for (const nlohmann::json& r : page->rows) rows.push_back(r);
    return rows;
  }
};

TEST_F(WalkerJobs, EvaluateStoresTheStartingGait) {
  const auto rows = run("eval-1", walker_spec("evaluate"), 1);
  ASSERT_EQ(rows.size(), 1u);
  std::printf("evaluate row: %s\n", rows[0].dump().substr(0, 300).c_str());
  const nlohmann::json values = rows[0]["values"];
  EXPECT_TRUE(values["gait"]["real"].get<bool>());
  EXPECT_NEAR(values["gait"]["mean_speed"].get<double>(), 1.0, 1e-8);
  EXPECT_EQ(values["x"].size(), 20u);  // point feet: (M - 1) n_b = 5 x 4
}

TEST_F(WalkerJobs, OptimiseLowersTheCostOfTransport) {
  const auto rows = run("opt-1", walker_spec("optimise"), 1);
  ASSERT_EQ(rows.size(), 1u);
  const nlohmann::json values = rows[0]["values"];
  const double start = values["start_objective"].get<double>(), end = values["gait"]["objective"].get<double>();
  std::printf("optimise: f_mech %.5f -> %.5f, %s after %d iterations\n", start, end,
              values["solver"]["termination"].get<std::string>().c_str(), values["solver"]["iterations"].get<int>());
  EXPECT_LT(end, start);
  EXPECT_TRUE(values["gait"]["real"].get<bool>());
  EXPECT_TRUE(values["solver"]["success"].get<bool>());
}

TEST_F(WalkerJobs, SweepStoresOnePointPerSpeed) {
  nlohmann::json spec = walker_spec("sweep");
  spec.erase("speed");
  spec["speeds"] = "0.8:0.2:1.2";
  const auto rows = run("sweep-1", spec, 3);
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& r : rows) {
    const nlohmann::json values = r["values"];
    std::printf("sweep v = %.1f: f_mech %.5f, %s after %d iterations (%s)\n", r["parameter"].get<double>(),
                values["gait"]["objective"].get<double>(), values["solver"]["termination"].get<std::string>().c_str(),
                values["solver"]["iterations"].get<int>(), values["start"].get<std::string>().substr(0, 40).c_str());
    EXPECT_TRUE(values["gait"]["real"].get<bool>());
    EXPECT_TRUE(values["solver"]["success"].get<bool>());
    EXPECT_NEAR(values["gait"]["mean_speed"].get<double>(), r["parameter"].get<double>(), 1e-8);
  }
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
