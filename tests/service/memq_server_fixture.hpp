#pragma once
// A fresh results database in a per-test temporary folder, the built-in job kinds, and a client
// on an in-process memq:// LCM: what every in-process server test starts from.
#include "cyclopt/service/builtin_job_kinds.hpp"
#include "server.hpp"
#include "service_client.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace cyclopt::testing {

class MemqServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("cyclopt_memq_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    config_.database = (dir_ / "results.db").string();
    config_.workers = 2;
    ASSERT_TRUE(lcm_.good());
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;
  server::ServerConfig config_;
  service::JobKindRegistry kinds_ = service::builtin_job_kinds();
  lcm::LCM lcm_{"memq://"};
  client::ServiceClient client_{lcm_};
};

}  // namespace cyclopt::testing
