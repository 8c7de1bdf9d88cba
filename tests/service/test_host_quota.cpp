// The unauthenticated queue quota is per sending host (issue 57 item 4): over udpm:// the server's
// own receiver reads each datagram's source address, so one host that fills its quota leaves the
// others theirs. The test moves into a network namespace of its own (root or CAP_SYS_ADMIN, else
// skipped) with multicast routed to lo, and sends submissions from two loopback addresses.
#include "cyclopt/jobs/builtin_job_kinds.hpp"
#include "cyclopt_channels.hpp"
#include "server.hpp"
#include "service_client.hpp"
#include "wire_mutations.hpp"

#include <cyclopt_lcm/job_submit_t.hpp>

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sched.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <thread>

namespace cyclopt {
namespace {

constexpr const char* kUrl = "udpm://239.255.76.67:7667?ttl=0";

// Sends job_submit_t datagrams from the loopback address `host`.
class HostSender {
 public:
  explicit HostSender(const char* host) : fd_(socket(AF_INET, SOCK_DGRAM, 0)) {
    sockaddr_in from{};
    from.sin_family = AF_INET;
    inet_pton(AF_INET, host, &from.sin_addr);
    ok_ = fd_ >= 0 && bind(fd_, reinterpret_cast<const sockaddr*>(&from), sizeof from) == 0;
    const unsigned char ttl = 0;
    setsockopt(fd_, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl);
    in_addr via{};
    inet_pton(AF_INET, host, &via);
    setsockopt(fd_, IPPROTO_IP, IP_MULTICAST_IF, &via, sizeof via);
  }
  ~HostSender() { close(fd_); }
  bool ok() const { return ok_; }
  void submit(const std::string& request_id, const std::string& spec) {
    cyclopt_lcm::job_submit_t m;
    m.request_id = request_id;
    m.spec_json = spec;
    const std::string d = testing::short_datagram(channels::kSubmit, wire::encode(m), ++seqno_);
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(7667);
    inet_pton(AF_INET, "239.255.76.67", &to.sin_addr);
    sendto(fd_, d.data(), d.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to);
  }

 private:
  int fd_;
  bool ok_ = false;
  std::uint32_t seqno_ = 0;
};

std::string long_sweep() {
  return nlohmann::json{{"scene", "walker"},
                        {"task", "foot_sweep"},
                        {"foot", "P2-shoes-left-HMT"},
                        {"samples", 13},
                        {"point_delay_ms", 50},
                        {"sweep", {{"parameter", "density"}, {"values", "1:1:200"}}}}
      .dump();
}

TEST(HostQuota, OneHostFillingItsQuotaLeavesOtherHostsTheirs) {
  if (unshare(CLONE_NEWNET) != 0) GTEST_SKIP() << "cannot create a network namespace (needs root / CAP_SYS_ADMIN)";
  ASSERT_EQ(std::system("ip link set lo up && ip route add 224.0.0.0/4 dev lo"), 0);
  const auto dir = std::filesystem::temp_directory_path() / ("cyclopt_host_quota_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  server::ServerConfig config;
  config.database = (dir / "results.db").string();
  config.lcm_url = kUrl;
  config.workers = 1;
  config.quota.max_queued_jobs = 3;
  const service::JobKindRegistry kinds = jobs::builtin_job_kinds();
  lcm::LCM server_lcm(kUrl), client_lcm(kUrl);
  ASSERT_TRUE(server_lcm.good() && client_lcm.good());
  std::atomic<bool> stop{false};
  {
    server::Server srv(config, kinds, server_lcm);
    std::thread serving([&] { srv.serve(stop); });
    client::ServiceClient listener(client_lcm, kUrl);  // reads the acks
    HostSender a("127.0.0.2"), b("127.0.0.3");
    ASSERT_TRUE(a.ok() && b.ok());
    // Each submission is answered before the next is sent (send_raw waits for its ack).
    auto ack_from = [&](HostSender& host, const std::string& id) {
      std::optional<cyclopt_lcm::job_ack_t> ack;
      for (int tries = 0; tries < 10 && !ack; ++tries) {
        std::thread send([&] {
          std::this_thread::sleep_for(std::chrono::milliseconds(50));
          host.submit(id, long_sweep());
        });
        ack = listener.send_raw("CYCLOPT_NOBODY", "", id, 1.0);  // publishes nothing anyone reads; waits for id's ack
        send.join();
      }
      return ack;
    };
    int accepted_a = 0;
    std::optional<cyclopt_lcm::job_ack_t> refused;
    for (int i = 0; i < 8 && !refused; ++i) {
      const auto ack = ack_from(a, "a-" + std::to_string(i));
      ASSERT_TRUE(ack) << "no answer to host a's submission " << i;
      if (ack->accepted)
        ++accepted_a;
      else
        refused = ack;
    }
    ASSERT_TRUE(refused) << "host a was never refused";
    EXPECT_EQ(refused->field, "queue") << refused->problem;
    EXPECT_NE(refused->problem.find("host 127.0.0.2"), std::string::npos) << refused->problem;
    EXPECT_LE(accepted_a, 4);  // 3 queued + at most one already running
    const auto from_b = ack_from(b, "b-0");
    ASSERT_TRUE(from_b);
    EXPECT_TRUE(from_b->accepted) << "host b was refused: " << from_b->problem;
    stop = true;
    serving.join();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cyclopt
