// cyclopt-web's settings (web/dashboard_config.hpp): loopback unless asked otherwise, the server's
// config file read for what both share, bad flags named.
#include "dashboard_config.hpp"

#include "cyclopt/errors/spec_error.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

using namespace cyclopt;

TEST(DashboardConfig, LoopbackUnlessAllowed) {
  const web::DashboardConfig plain = web::dashboard_config_from_args({});
  EXPECT_EQ(plain.host, "127.0.0.1");
  EXPECT_EQ(plain.port, 8080);
  EXPECT_EQ(web::dashboard_config_from_args({"--listen", "[::1]:9000"}).host, "::1");
  try {
    web::dashboard_config_from_args({"--listen", "0.0.0.0:8080"});
    FAIL() << "a non-loopback address was accepted without --allow-remote";
  } catch (const SpecError& e) {
    EXPECT_EQ(e.field(), "--listen");
  }
  const web::DashboardConfig remote = web::dashboard_config_from_args({"--listen", "0.0.0.0:8080", "--allow-remote"});
  EXPECT_EQ(remote.host, "0.0.0.0");
  for (const char* bad : {"8080", "127.0.0.1:", "127.0.0.1:0", "127.0.0.1:65536", "127.0.0.1:80x"})
    EXPECT_THROW(web::dashboard_config_from_args({"--listen", bad}), SpecError) << bad;
  EXPECT_THROW(web::dashboard_config_from_args({"--refresh-seconds", "0"}), SpecError);
  EXPECT_THROW(web::dashboard_config_from_args({"--workers", "2"}), SpecError);
}

TEST(DashboardConfig, SharesTheServersConfigFile) {
  const std::string path = ::testing::TempDir() + "cycloptd_for_web.json";
  std::ofstream(path) << R"({"database": "/srv/cyclopt.db", "workers": 4, "lcm_url": "memq://",
                            "auth_secret_file": "/etc/cyclopt/keys", "auth_reads": "any"})";
  const web::DashboardConfig c = web::dashboard_config_from_args({"--config", path});
  EXPECT_EQ(c.database, "/srv/cyclopt.db");
  EXPECT_EQ(c.lcm_url, "memq://");
  EXPECT_EQ(c.auth_secret_file, "/etc/cyclopt/keys");
  EXPECT_TRUE(c.auth_reads_any);
  std::ofstream(path) << R"({"auth_reads": "everyone"})";
  EXPECT_THROW(web::dashboard_config_from_args({"--config", path}), SpecError);
  std::remove(path.c_str());
}
