// Fuzz test of every channel the server and the client read (issue 19, acceptance 1): valid
// encodings of all seven message types mutated field by field (wire_mutations.hpp) go through
// the real handlers of an in-process server and client, and LC02/LC03 datagrams with lying
// headers go through the datagram assembler with the completed messages routed to the same
// handlers. Afterwards the server must still accept, answer and cancel a job. Reports the
// inputs tried and the peak RSS.
#include "cyclopt_channels.hpp"
#include "lcm_datagrams.hpp"
#include "memq_server_fixture.hpp"
#include "wire_mutations.hpp"

#include <cyclopt_lcm/job_cancel_t.hpp>
#include <cyclopt_lcm/job_submit_t.hpp>
#include <cyclopt_lcm/query_request_t.hpp>

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>

namespace cyclopt {
namespace {

std::string random_text(std::mt19937_64& rng, std::size_t max) {
  std::string s(rng() % (max + 1), ' ');
  for (char& c : s) c = static_cast<char>(0x21 + rng() % 94);
  return s;
}

// One valid encoding per message type, with random contents; the channel it travels on.
struct Sample {
  const char* channel;
  std::string bytes;
  std::span<const wire::Field> fields;
};

std::vector<Sample> samples(std::mt19937_64& rng) {
  const double nan = std::nan("");
  cyclopt_lcm::job_submit_t submit;
  submit.request_id = "fuzz-" + std::to_string(rng() % 1000);
  submit.spec_json = R"({"scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT", "point_delay_ms": 0, )"
                     R"("sweep": {"parameter": "density", "values": "1:1:2"}})";
  cyclopt_lcm::job_cancel_t cancel;
  cancel.request_id = random_text(rng, 40);
  cancel.job_id = static_cast<std::int64_t>(rng() % 5);
  cyclopt_lcm::query_request_t query;
  query.request_id = random_text(rng, 40);
  query.what = std::vector<std::string>{"jobs", "job", "solutions", "events", "curves", "trajectories"}[rng() % 6];
  query.job_id = 1;
  query.state = rng() % 2 ? "" : "queued";
  query.offset = static_cast<int>(rng() % 3);
  query.limit = 1 + static_cast<int>(rng() % 100);
  query.part_offset = 0;
  cyclopt_lcm::job_ack_t ack{random_text(rng, 40), true, 7, false, "queued", "", random_text(rng, 60)};
  cyclopt_lcm::job_progress_t progress{7,   random_text(rng, 32), "foot_sweep", 123456, 3, 0.5, nan, 1.0, 0, 1, 2, 50.0,
                                       rng() % 2 == 0, nan, random_text(rng, 80), random_text(rng, 40), 2, 20, 0.25, 12.5};
  cyclopt_lcm::job_done_t done{7, random_text(rng, 32), "done", 2, 1.5, 0.001, "", 2, 2};
  cyclopt_lcm::query_reply_t reply{random_text(rng, 40), 0, 1, 1, -1, R"([{"id": 7, "state": "done"}])", "", 0, 0};
  return {{channels::kSubmit, wire::encode(submit), wire::LcmLayout<cyclopt_lcm::job_submit_t>::fields},
          {channels::kCancel, wire::encode(cancel), wire::LcmLayout<cyclopt_lcm::job_cancel_t>::fields},
          {channels::kQuery, wire::encode(query), wire::LcmLayout<cyclopt_lcm::query_request_t>::fields},
          {channels::kAck, wire::encode(ack), wire::LcmLayout<cyclopt_lcm::job_ack_t>::fields},
          {channels::kProgress, wire::encode(progress), wire::LcmLayout<cyclopt_lcm::job_progress_t>::fields},
          {channels::kDone, wire::encode(done), wire::LcmLayout<cyclopt_lcm::job_done_t>::fields},
          {channels::kQueryReply, wire::encode(reply), wire::LcmLayout<cyclopt_lcm::query_reply_t>::fields}};
}

TEST(WireCheck, EveryLayoutMatchesItsGeneratedEncoder) {
  std::mt19937_64 rng(1);
  for (const Sample& s : samples(rng)) {
    const std::span<const std::uint8_t> bytes = wire::as_bytes(s.bytes);
    EXPECT_EQ(testing::field_spans(s.bytes, s.fields).back().at + testing::field_spans(s.bytes, s.fields).back().size, s.bytes.size())
        << s.channel;
    EXPECT_EQ(wire::encoding_problem(bytes, testing::read_be(s.bytes, 0, 8), s.fields, s.channel), "") << s.channel;
  }
}

TEST(WireCheck, NamesTheFieldOfABadLength) {
  cyclopt_lcm::job_submit_t m;
  m.request_id = "abc";
  m.spec_json = "{}";
  for (std::int32_t len : {0, -1, INT_MIN}) {
    std::string b = wire::encode(m);
    testing::write_be(b, 8, 4, static_cast<std::uint32_t>(len));
    std::string problem;
    EXPECT_FALSE(wire::decode_checked<cyclopt_lcm::job_submit_t>(wire::as_bytes(b), problem));
    EXPECT_NE(problem.find("job_submit_t.request_id at byte 8: string length " + std::to_string(len)), std::string::npos)
        << problem;
  }
  EXPECT_FALSE(wire::is_utf8("\xc0\xaf"));
  EXPECT_FALSE(wire::is_utf8("\xed\xa0\x80"));
  EXPECT_TRUE(wire::is_utf8("L\xc3\xa4nge \xe2\x82\xac \xf0\x9f\x98\x80"));
}

TEST(DatagramAssembler, ReassemblesAndBoundsLyingFragments) {
  std::mt19937_64 rng(2);
  const std::string payload = random_text(rng, 5000) + std::string(3000, 'p');
  wire::DatagramAssembler a({.max_message_bytes = 1 << 16, .max_pending_bytes = 1 << 18, .stale_seconds = 2.0});
  const auto feed_all = [&](const std::vector<std::string>& seq, std::uint64_t sender, double t) {
    std::optional<wire::LcmMessage> last;
    for (const std::string& d : seq)
      if (auto m = a.feed(wire::as_bytes(d), sender, t)) last = m;
    return last;
  };
  const auto good = feed_all(testing::fragments("CH", payload, 1, 1400), 1, 0.0);
  ASSERT_TRUE(good);
  EXPECT_EQ(good->channel, "CH");
  EXPECT_EQ(std::string(good->payload.begin(), good->payload.end()), payload);
  int completed_intact = 0, seq = 0;
  for (const auto& lie : testing::lying_fragments("CH", payload, 2, rng)) {
    ++seq;
    const auto m = feed_all(lie, 10 + static_cast<std::uint64_t>(seq % 50), 0.01 * seq);
    if (m && std::string(m->payload.begin(), m->payload.end()) == payload) ++completed_intact;
    EXPECT_LE(a.pending_bytes(), std::size_t{1} << 18);
  }
  EXPECT_GT(a.counters().malformed, 50);
  // A repeated fragment or one whose fields are unchanged still assembles; after all the lies a
  // fresh message from a known sender still does.
  EXPECT_GT(completed_intact, 0);
  EXPECT_TRUE(feed_all(testing::fragments("CH", payload, 99, 1000), 10, 100.0));
  EXPECT_TRUE(a.feed(wire::as_bytes(testing::short_datagram("CH", "x", 5)), 3, 100.0));
  EXPECT_FALSE(a.feed(wire::as_bytes(testing::short_datagram(std::string(64, 'C'), "x", 5)), 3, 100.0));
  EXPECT_FALSE(a.feed(wire::as_bytes(std::string("LC02\0\0\0\0CH", 10)), 3, 100.0));  // no NUL after the channel
}

class WireFuzz : public testing::MemqServerTest {};

TEST_F(WireFuzz, NoInputStopsTheServerOrTheClient) {
  config_.workers = 1;
  server::Server srv(config_, kinds_, lcm_);
  lcm::LCM client_lcm("memq://");  // the client's handlers, fed directly
  client::ServiceClient peer(client_lcm);
  server::RequestHandler& handler = srv.handler();
  const std::map<std::string, std::function<void(std::span<const std::uint8_t>)>> route = {
      {channels::kSubmit, [&](auto p) { handler.on_submit(p); }},
      {channels::kCancel, [&](auto p) { handler.on_cancel(p); }},
      {channels::kQuery, [&](auto p) { handler.on_query(p); }},
      {channels::kAck, [&](auto p) { peer.on_ack(p); }},
      {channels::kProgress, [&](auto p) { peer.on_progress(p); }},
      {channels::kDone, [&](auto p) { peer.on_done(p); }},
      {channels::kQueryReply, [&](auto p) { peer.on_query_reply(p); }}};
  std::map<std::string, long> per_channel;
  long inputs = 0, datagrams = 0;
  const auto t0 = std::chrono::steady_clock::now();
  std::mt19937_64 rng(19);
  wire::DatagramAssembler assembler;
  std::uint32_t seqno = 0;
  for (int round = 0; round < 18; ++round) {
    for (const Sample& s : samples(rng)) {
      const auto& deliver = route.at(s.channel);
      for (const std::string& m : testing::mutations(s.bytes, s.fields, rng, 600)) {
        deliver(wire::as_bytes(m));
        ++inputs;
        ++per_channel[s.channel];
        // Every 7th mutation also travels as a (lying) datagram sequence through the assembler.
        if (inputs % 7 != 0) continue;
        const auto lies = testing::lying_fragments(s.channel, m.empty() ? std::string("x") : m, ++seqno, rng);
        for (const std::string& d : lies[rng() % lies.size()]) {
          ++datagrams;
          if (auto msg = assembler.feed(wire::as_bytes(d), rng() % 8, 0.001 * static_cast<double>(datagrams)))
            if (route.count(msg->channel)) route.at(msg->channel)(msg->payload);
        }
        ++datagrams;
        if (auto msg = assembler.feed(wire::as_bytes(testing::short_datagram(s.channel, m, seqno)), 9, 0.0))
          route.at(msg->channel)(msg->payload);
      }
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  std::printf("wire fuzz: %ld encodings (", inputs);
  for (const auto& [channel, n] : per_channel) std::printf("%s %ld, ", channel.c_str(), n);
  std::printf("), %ld datagrams (%ld malformed, %ld messages assembled), %.1f s, peak RSS %ld MiB; server: %ld rejected, "
              "%ld accepted; client: %ld malformed ignored\n",
              datagrams, assembler.counters().malformed, assembler.counters().messages, seconds, ru.ru_maxrss / 1024,
              srv.counters().rejected.load(), srv.counters().accepted.load(), peer.malformed_received());
  EXPECT_GE(inputs + datagrams, 100000);
  EXPECT_LT(ru.ru_maxrss / 1024, 1024);
  EXPECT_LE(assembler.pending_bytes(), wire::AssemblerLimits{}.max_pending_bytes);

  // Still alive and answering: a submission is acknowledged, queried and cancelled.
  const std::string spec = R"({"scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT", )"
                           R"("point_delay_ms": 100, "sweep": {"parameter": "density", "values": "1:1:100"}})";
  const auto ack = client_.submit("after-the-fuzz", spec, 10.0);
  ASSERT_TRUE(ack);
  EXPECT_TRUE(ack->accepted) << ack->problem;
  const auto page = client_.query(storage::query_for("job", ack->job_id), 10.0);
  ASSERT_TRUE(page);
  ASSERT_EQ(page->rows.size(), 1u);
  EXPECT_EQ(page->rows[0]["request_id"], "after-the-fuzz");
  const auto cancelled = client_.cancel(ack->job_id, 10.0);
  ASSERT_TRUE(cancelled);
  EXPECT_TRUE(cancelled->accepted) << cancelled->problem;
}

}  // namespace
}  // namespace cyclopt
