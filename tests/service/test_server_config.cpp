// cycloptd settings: defaults, config file, flags overriding it, errors naming the setting.
#include "server_config.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace cyclopt::server {
namespace {

TEST(ServerConfig, FlagsOverrideTheConfigFile) {
  const auto path = std::filesystem::temp_directory_path() / "cyclopt_test_cycloptd.json";
  std::ofstream(path) << R"({"database": "a.db", "workers": 3, "max_job_seconds": 60, "progress_hz": 2})";
  const ServerConfig c = server_config_from_args({"--config", path.string(), "--workers", "1", "--lcm-url", "memq://"});
  std::filesystem::remove(path);
  EXPECT_EQ(c.database, "a.db");
  EXPECT_EQ(c.workers, 1);
  EXPECT_EQ(c.lcm_url, "memq://");
  EXPECT_EQ(c.caps.max_wall_seconds, 60.0);
  EXPECT_EQ(c.progress_hz, 2.0);
  EXPECT_EQ(effective_workers(ServerConfig{}), std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
}

TEST(ServerConfig, BadSettingsAreNamed) {
  auto message = [](const std::vector<std::string>& args) {
    try {
      server_config_from_args(args);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message({"--workers", "0"}).find("workers"), std::string::npos);
  EXPECT_NE(message({"--workers", "two"}).find("workers"), std::string::npos);
  EXPECT_NE(message({"--progress-hz", "1000"}).find("progress_hz"), std::string::npos);
  EXPECT_NE(message({"--colour", "red"}).find("colour"), std::string::npos);
  EXPECT_NE(message({"--database"}).find("--database"), std::string::npos);
  EXPECT_NE(message({"--config", "/nonexistent/cycloptd.json"}).find("--config"), std::string::npos);
}

}  // namespace
}  // namespace cyclopt::server
