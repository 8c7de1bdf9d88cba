// cyclopt-bad-sender: integration-test helper. Sends N malformed messages to cycloptd, one at a
// time, cycling through: garbage bytes, truncated LCM encodings, malformed JSON, wrong types,
// out-of-range values, oversize specs, bad request ids, bad cancels and bad queries. Waits for
// each answer and checks that it is a rejection naming the expected field.
// usage: cyclopt-bad-sender --lcm-url URL --count N     exit 0 iff every message was answered so
#include <cyclopt_lcm/job_cancel_t.hpp>
#include <cyclopt_lcm/job_submit_t.hpp>

#include "cyclopt_channels.hpp"
#include "service_client.hpp"

#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace {

struct BadMessage {
  std::string channel;
  std::string bytes;
  std::string reply_id;  // request id the rejection carries ("" for undecodable bytes)
  std::string field;     // the field the rejection must name
};

std::string submit_bytes(const std::string& id, const std::string& spec) {
  cyclopt_lcm::job_submit_t m;
  m.request_id = id;
  m.spec_json = spec;
  return cyclopt::wire::encode(m);
}

BadMessage make(int i, std::mt19937& rng) {
  const std::string id = "bad-" + std::to_string(i) + "-" + cyclopt::client::new_request_id().substr(0, 8);
  const std::string foot = R"("scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT")";
  switch (i % 10) {
    case 0: {  // random bytes
      std::string b(1 + rng() % 300, '\0');
      for (char& c : b) c = static_cast<char>(rng());
      return {cyclopt::channels::kSubmit, b, "", cyclopt::channels::kSubmit};
    }
    case 1: {  // a valid encoding cut short
      const std::string full = submit_bytes(id, "{\"scene\": \"walker\"}");
      return {cyclopt::channels::kSubmit, full.substr(0, 8 + rng() % (full.size() - 9)), "", cyclopt::channels::kSubmit};
    }
    case 2:
      return {cyclopt::channels::kSubmit, submit_bytes(id, "{\"scene\": \"walker\", \"task\": [1, 2"), id, "spec_json"};
    case 3:
      return {cyclopt::channels::kSubmit, submit_bytes(id, "{" + foot + ", \"sweep\": {\"parameter\": 5, \"values\": 1}}"),
              id, "sweep.parameter"};
    case 4:
      return {cyclopt::channels::kSubmit,
              submit_bytes(id, "{" + foot + R"(, "sweep": {"parameter": "density", "values": "1:1:5000"}})"), id,
              "sweep.values"};
    case 5:
      return {cyclopt::channels::kSubmit,
              submit_bytes(id, "{" + foot + R"(, "sweep": {"parameter": "density", "values": 30}, "limits": {"max_wall_seconds": -3}})"),
              id, "limits.max_wall_seconds"};
    case 6:
      return {cyclopt::channels::kSubmit, submit_bytes(id, std::string(cyclopt::channels::kMaxSpecBytes + 1 + rng() % 20000, '{')),
              id, "spec_json"};
    case 7:
      return {cyclopt::channels::kSubmit, submit_bytes(id + " with spaces", "{}"), id + " with spaces", "request_id"};
    case 8: {
      cyclopt_lcm::job_cancel_t c;
      c.request_id = id;
      c.job_id = -5 - i;
      return {cyclopt::channels::kCancel, cyclopt::wire::encode(c), id, "job_id"};
    }
    default: {
      std::string b = "garbage on the query channel " + std::to_string(rng());
      return {cyclopt::channels::kQuery, b, "", cyclopt::channels::kQuery};
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string url;
  int count = 1000;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--lcm-url") url = argv[i + 1];
    else if (a == "--count") count = std::stoi(argv[i + 1]);
  }
  url = cyclopt::wire::resolved_lcm_url(url);
  lcm::LCM lcm(url);
  if (!lcm.good()) return 2;
  cyclopt::client::ServiceClient client(lcm, url);
  std::mt19937 rng(12345);
  int answered = 0, named = 0;
  for (int i = 0; i < count; ++i) {
    const BadMessage m = make(i, rng);
    auto ack = client.send_raw(m.channel, m.bytes, m.reply_id, 2.0);
    if (!ack) ack = client.send_raw(m.channel, m.bytes, m.reply_id, 2.0);  // one retry for a lost datagram
    if (!ack) {
      std::fprintf(stderr, "no answer to message %d (%s, %zu bytes)\n", i, m.channel.c_str(), m.bytes.size());
      continue;
    }
    ++answered;
    if (!ack->accepted && ack->field == m.field && ack->problem.find(m.field) != std::string::npos)
      ++named;
    else
      std::fprintf(stderr, "message %d: expected a rejection naming %s, got field '%s': %s\n", i, m.field.c_str(),
                   ack->field.c_str(), ack->problem.c_str());
  }
  std::printf("bad messages sent %d, answered %d, rejected naming the problem %d\n", count, answered, named);
  return named == count ? 0 : 1;
}
