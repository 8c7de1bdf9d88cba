#pragma once
// A fresh results database in a per-test temporary folder, the built-in job kinds, and a client
// on an in-process memq:// LCM: what every in-process server test starts from.
#include "cyclopt/jobs/builtin_job_kinds.hpp"
#include "server.hpp"
#include "service_client.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

namespace cyclopt::testing {

class MemqServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("cyclopt_memq_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));  // worktrees and parallel ctest runs do not share folders
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    config_.database = (dir_ / "results.db").string();
    config_.workers = 2;
    ASSERT_TRUE(lcm_.good());
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Runs one job on a server of its own: submits, waits for completion and returns the stored
  // solution rows (expected_points < 0: any number).
  std::vector<nlohmann::json> run_job(const std::string& id, const nlohmann::json& spec, int expected_points) {
    server::Server srv(config_, kinds_, lcm_);
    const auto ack = client_.submit(id, spec.dump(), 5.0);
    EXPECT_TRUE(ack && ack->accepted) << (ack ? ack->problem : "no ack");
    if (!ack || !ack->accepted) return {};
    // The longest job here takes ~85 s on 2 idle cores and over 120 s on a loaded machine; the wait
    // stays below ctest's 600 s so that a hung job still fails here, naming the job.
    const auto done = client_.watch(ack->job_id, [](const cyclopt_lcm::job_progress_t&) {}, 400.0);
    EXPECT_TRUE(done);
    if (!done) return {};
    EXPECT_EQ(done->state, "done") << done->error;
    if (expected_points >= 0) {
      EXPECT_EQ(done->points_stored, expected_points);
    }
    const auto page = client_.query(storage::query_for("solutions", ack->job_id), 5.0);
    EXPECT_TRUE(page);
    std::vector<nlohmann::json> rows;
    if (page)
      for (const nlohmann::json& r : page->rows) rows.push_back(r);
    return rows;
  }

  std::filesystem::path dir_;
  server::ServerConfig config_;
  service::JobKindRegistry kinds_ = jobs::builtin_job_kinds();
  lcm::LCM lcm_{"memq://"};
  client::ServiceClient client_{lcm_};
};

}  // namespace cyclopt::testing
