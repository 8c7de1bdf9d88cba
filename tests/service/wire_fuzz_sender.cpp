// cyclopt-wire-fuzz: integration-test helper for the fuzz test of issue 19. Sends hostile LCM
// datagrams straight to a multicast group (plain UDP, not liblcm, so that headers can lie):
// mutated encodings of every message type in LC02 datagrams on their channels, and LC03
// fragment sequences with lying headers.
// usage: cyclopt-wire-fuzz GROUP PORT COUNT [--only-liblcm-killer | --seed N]
//   prints the number of datagrams sent; --only-liblcm-killer sends just the one datagram that
//   brings down liblcm 1.3.1's receiver (fragment offset + length wrapping past 2^32); --seed
//   seeds the mutations (default 1919), so that a run that found something can be replayed.
#include "cyclopt_channels.hpp"
#include "wire_mutations.hpp"

#include <cyclopt_lcm/job_ack_t.hpp>
#include <cyclopt_lcm/job_cancel_t.hpp>
#include <cyclopt_lcm/job_done_t.hpp>
#include <cyclopt_lcm/job_progress_t.hpp>
#include <cyclopt_lcm/job_submit_t.hpp>
#include <cyclopt_lcm/query_reply_t.hpp>
#include <cyclopt_lcm/query_request_t.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>

namespace {

struct Sample {
  const char* channel;
  std::string bytes;
  std::span<const cyclopt::wire::Field> fields;
};

template <class T>
Sample sample(const char* channel, const T& m) {
  return {channel, cyclopt::wire::encode(m), cyclopt::wire::LcmLayout<T>::fields};
}

// Job ids far from the real ones, so that a well-formed mutation cannot end a real watch.
constexpr std::int64_t kForeignJob = 900000001;

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: cyclopt-wire-fuzz GROUP PORT COUNT [--only-liblcm-killer | --seed N]\n");
    return 1;
  }
  const int fd = socket(AF_INET, SOCK_DGRAM, 0);
  const unsigned char ttl = 0;
  setsockopt(fd, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl);
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(static_cast<std::uint16_t>(std::atoi(argv[2])));
  inet_pton(AF_INET, argv[1], &to.sin_addr);
  const long count = std::atol(argv[3]);
  long sent = 0;
  const auto send = [&](const std::string& d) {
    if (sendto(fd, d.data(), d.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to) >= 0) ++sent;
    if (sent % 64 == 0) std::this_thread::sleep_for(std::chrono::microseconds(500));  // let receivers keep up
  };
  const bool seeded = argc > 5 && std::string(argv[4]) == "--seed";
  std::mt19937_64 rng(seeded ? std::strtoull(argv[5], nullptr, 10) : 1919);
  if (argc > 4 && std::string(argv[4]) == "--only-liblcm-killer") {
    const auto lies = cyclopt::testing::lying_fragments("CYCLOPT_SUBMIT", std::string(60, 'x'), 1, rng);
    send(lies.back()[0]);
    std::printf("%ld\n", sent);
    return 0;
  }
  const double nan = std::nan("");
  const std::vector<Sample> samples = {
      sample(cyclopt::channels::kSubmit,
             cyclopt_lcm::job_submit_t{"netns-fuzz", R"({"scene": "walker", "task": "foot_sweep", "foot": "nothing"})"}),
      sample(cyclopt::channels::kCancel, cyclopt_lcm::job_cancel_t{"netns-fuzz-cancel", kForeignJob}),
      sample(cyclopt::channels::kQuery, cyclopt_lcm::query_request_t{"netns-fuzz-query", "jobs", 0, "", 0, 5, 0}),
      sample(cyclopt::channels::kAck, cyclopt_lcm::job_ack_t{"netns-fuzz-ack", true, kForeignJob, false, "queued", "", ""}),
      sample(cyclopt::channels::kProgress,
             cyclopt_lcm::job_progress_t{kForeignJob, "x", "foot_sweep", 1, 2, 0.5, nan, 1.0, 0, 1, 2, 50.0, false, nan, "m", "p", 1, 2, nan, 1.0}),
      sample(cyclopt::channels::kDone, cyclopt_lcm::job_done_t{kForeignJob, "x", "done", 2, 1.5, 0.001, "", 2, 2}),
      sample(cyclopt::channels::kQueryReply,
             cyclopt_lcm::query_reply_t{"netns-fuzz-reply", 0, 1, 1, -1, R"([{"id": 1}])", "", 0, 0})};
  std::uint32_t seqno = 0;
  while (sent < count) {
    for (const Sample& s : samples) {
      for (const std::string& m : cyclopt::testing::mutations(s.bytes, s.fields, rng, 100)) {
        send(cyclopt::testing::short_datagram(s.channel, m, ++seqno));
        if (seqno % 5 != 0) continue;
        const auto lies = cyclopt::testing::lying_fragments(s.channel, m.empty() ? std::string("x") : m, seqno, rng);
        for (const std::string& d : lies[rng() % lies.size()]) send(d);
      }
      if (sent >= count) break;
    }
  }
  close(fd);
  std::printf("%ld\n", sent);
  return 0;
}
