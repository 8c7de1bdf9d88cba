// cyclopt-web's HTTP side against a real database on loopback (web/dashboard_server.hpp): a job's
// event stream opened before the live fleet has read the job must neither stop the program nor
// stay silent once the fleet knows the job.
#include "dashboard_server.hpp"
#include "store_rows.hpp"

#include "cyclopt/storage/result_store.hpp"
#include "cyclopt/storage_read/result_queries.hpp"

#include <gtest/gtest.h>
#include <httplib.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>

using namespace cyclopt;

namespace {

// A loopback port no one listens on now: the kernel's choice for port 0 (another program could take
// it before the dashboard binds it, a far smaller window than any fixed choice).
int unused_loopback_port() {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t n = sizeof a;
  if (s < 0 || ::bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 ||
      ::getsockname(s, reinterpret_cast<sockaddr*>(&a), &n) != 0)
    throw std::runtime_error("no loopback port");
  ::close(s);
  return ntohs(a.sin_port);
}

struct RunningDashboard {
  explicit RunningDashboard(const std::string& db) : store(db) {
    config.database = db;
    config.port = unused_loopback_port();
    server.emplace(config, store, fleet, std::nullopt);
    thread = std::thread([this] { server->listen(); });
    for (int i = 0; i < 200 && !httplib::Client("127.0.0.1", config.port).Get("/static/dashboard.css"); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ~RunningDashboard() {
    fleet.stop();
    server->stop();
    thread.join();
  }
  // What /api/job/ID/events sends within `seconds` (the stream itself never ends).
  std::string events(std::int64_t id, double seconds) {
    httplib::Client c("127.0.0.1", config.port);
    std::string text;
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    c.set_read_timeout(std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::duration<double>(seconds)));
    c.Get("/api/job/" + std::to_string(id) + "/events", [&](const char* data, std::size_t n) {
      text.append(data, n);
      return std::chrono::steady_clock::now() < until;
    });
    return text;
  }
  web::DashboardConfig config;
  storage::ResultStore store;
  web::LiveFleet fleet;
  std::optional<web::DashboardServer> server;
  std::thread thread;
};

}  // namespace

TEST(DashboardServer, AJobPageOpenedBeforeTheFleetKnowsTheJobKeepsTheProgramAlive) {
  const std::string db = (std::filesystem::temp_directory_path() / ("dashboard_server_" + std::to_string(getpid()) + ".db")).string();
  std::filesystem::remove(db);
  {
    RunningDashboard d(db);
    const std::int64_t id = d.store.submit("r1", "walker", "sweep", R"({"scene": "walker", "task": "sweep", "foot": "point"})").job_id;
    // The job is in the database, not yet in the live fleet (cycloptd's refresher has not run).
    d.events(id, 0.5);
    const auto page = httplib::Client("127.0.0.1", d.config.port).Get("/job/" + std::to_string(id));
    ASSERT_TRUE(page) << "cyclopt-web stopped answering";
    EXPECT_EQ(page->status, 200);
    d.fleet.refresh(web::all_rows(d.store, storage::query_for("jobs")));
    const std::string text = d.events(id, 0.5);
    EXPECT_NE(text.find("event: job\ndata: {"), std::string::npos) << text;
    EXPECT_NE(text.find("\"state\":\"queued\""), std::string::npos) << text;
  }
  std::filesystem::remove(db);
}
