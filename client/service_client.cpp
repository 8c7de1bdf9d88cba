#include "service_client.hpp"

#include <cyclopt_lcm/job_cancel_t.hpp>
#include <cyclopt_lcm/job_submit_t.hpp>
#include <cyclopt_lcm/query_request_t.hpp>

#include "cyclopt_channels.hpp"

#include <algorithm>
#include <chrono>
#include <random>

namespace cyclopt::client {

namespace {
using Clock = std::chrono::steady_clock;
Clock::duration seconds(double s) { return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s)); }
}  // namespace

std::string new_request_id() {
  static thread_local std::mt19937_64 rng(std::random_device{}() ^
                                          static_cast<std::uint64_t>(Clock::now().time_since_epoch().count()));
  static constexpr char kHex[] = "0123456789abcdef";
  std::string id;
  for (int part = 0; part < 2; ++part) {
    std::uint64_t v = rng();
    for (int i = 0; i < 16; ++i, v >>= 4) id += kHex[v & 15];
  }
  return id;
}

ServiceClient::ServiceClient(lcm::LCM& lcm, const std::string& url, std::optional<wire::AuthKey> key) : bus_(lcm, url) {
  if (key) key_ = wire::KeyRing{{*key}};
  subscribe();
}

ServiceClient::ServiceClient(lcm::LCM& lcm, const std::string& url, wire::KeyRing believed)
    : bus_(lcm, url), key_(std::move(believed)) {
  subscribe();
}

void ServiceClient::subscribe() {
  bus_.subscribe(channels::kAck, [this](std::span<const std::uint8_t> p) { on_ack(p); });
  bus_.subscribe(channels::kProgress, [this](std::span<const std::uint8_t> p) { on_progress(p); });
  bus_.subscribe(channels::kDone, [this](std::span<const std::uint8_t> p) { on_done(p); });
  bus_.subscribe(channels::kQueryReply, [this](std::span<const std::uint8_t> p) { on_query_reply(p); });
}

template <class T>
std::optional<T> ServiceClient::checked(const char* channel, std::span<const std::uint8_t> raw) {
  const std::optional<wire::Signature> sig = wire::split_signature(raw);
  std::string problem;
  auto m = wire::decode_checked<T>(raw, problem);
  if (!m) {
    ++malformed_;
    return m;
  }
  if (key_ && !wire::verify_signature(*key_, sig, channel, raw, m->request_id, wire::unix_now_us(), problem)) {
    ++unverified_;
    return std::nullopt;
  }
  return m;
}

void ServiceClient::on_ack(std::span<const std::uint8_t> payload) {
  // The server's fixed answer to a signature it does not accept comes unsigned: believed as what
  // it says and nothing more (a forged one only ends the wait that silence would end too).
  std::span<const std::uint8_t> unsigned_part = payload;
  wire::split_signature(unsigned_part);
  std::string problem;
  const auto fixed = wire::decode_checked<cyclopt_lcm::job_ack_t>(unsigned_part, problem);
  if (fixed && !fixed->accepted && fixed->field == "signature" && fixed->problem == channels::kSignatureRejected &&
      awaiting_.count(fixed->request_id)) {
    signature_rejected_.insert(fixed->request_id);
    return;
  }
  const auto m = checked<cyclopt_lcm::job_ack_t>(channels::kAck, payload);
  if (m && awaiting_.count(m->request_id)) acks_[m->request_id] = *m;
}
void ServiceClient::on_progress(std::span<const std::uint8_t> payload) {
  const auto m = checked<cyclopt_lcm::job_progress_t>(channels::kProgress, payload);
  if (m && progress_callback_ && (m->job_id == watched_job_ || watched_job_ == kEveryJob)) (*progress_callback_)(*m);
}
void ServiceClient::on_done(std::span<const std::uint8_t> payload) {
  const auto m = checked<cyclopt_lcm::job_done_t>(channels::kDone, payload);
  if (m && m->job_id == watched_job_) done_[m->job_id] = *m;
}
void ServiceClient::on_query_reply(std::span<const std::uint8_t> payload) {
  const auto m = checked<cyclopt_lcm::query_reply_t>(channels::kQueryReply, payload);
  if (m && awaiting_.count(m->request_id)) replies_[m->request_id] = *m;
}

bool ServiceClient::pump_until(const std::function<bool()>& done, double s) {
  const auto deadline = Clock::now() + seconds(s);
  while (!done()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    bus_.handle_timeout(static_cast<int>(std::clamp<long long>(left, 1, 50)));
  }
  return true;
}

template <class Reply>
std::optional<Reply> ServiceClient::await(std::map<std::string, Reply>& answers, const std::string& id, double s) {
  const bool got = pump_until([&] { return answers.count(id) > 0 || signature_rejected_.count(id) > 0; }, s);
  if (!got) return std::nullopt;
  if (signature_rejected_.erase(id)) {
    awaiting_.erase(id);
    throw SignatureRejected(channels::kSignatureRejected);
  }
  Reply r = answers[id];
  answers.erase(id);
  return r;
}

std::optional<cyclopt_lcm::job_ack_t> ServiceClient::submit(const std::string& request_id, const std::string& spec_json,
                                                            double timeout_seconds, double retry_seconds) {
  cyclopt_lcm::job_submit_t msg;
  msg.request_id = request_id;
  msg.spec_json = spec_json;
  const auto deadline = Clock::now() + seconds(timeout_seconds);
  awaiting_.insert(request_id);
  std::optional<cyclopt_lcm::job_ack_t> ack;
  // Each round publishes once and then waits a full retry interval (or what is left).
  for (auto left = deadline - Clock::now(); !ack && left > std::chrono::milliseconds(1); left = deadline - Clock::now()) {
    bus_.publish(channels::kSubmit, msg, key_ ? &key_->keys[0] : nullptr);
    ack = await(acks_, request_id, std::min(retry_seconds, std::chrono::duration<double>(left).count()));
  }
  awaiting_.erase(request_id);
  return ack;
}

std::optional<cyclopt_lcm::job_ack_t> ServiceClient::cancel(std::int64_t job_id, double timeout_seconds) {
  cyclopt_lcm::job_cancel_t msg;
  msg.request_id = new_request_id();
  msg.job_id = job_id;
  awaiting_.insert(msg.request_id);
  bus_.publish(channels::kCancel, msg, key_ ? &key_->keys[0] : nullptr);
  auto ack = await(acks_, msg.request_id, timeout_seconds);
  awaiting_.erase(msg.request_id);
  return ack;
}

constexpr double kQueryRetrySeconds = 0.5;

std::optional<storage::QueryPage> ServiceClient::query(storage::QueryRequest request, double timeout_seconds) {
  storage::QueryPage all;
  const auto deadline = Clock::now() + seconds(timeout_seconds);
  int remaining = request.limit;
  std::string row_text;  // the parts of a row too large for one reply, so far
  while (true) {
    cyclopt_lcm::query_request_t msg;
    msg.request_id = new_request_id();
    msg.what = request.what;
    msg.job_id = request.job_id;
    msg.state = request.state;
    msg.offset = request.offset;
    msg.limit = std::min(remaining, channels::kMaxQueryLimit);
    msg.part_offset = static_cast<int>(row_text.size());
    awaiting_.insert(msg.request_id);
    // A query only reads: resent with the same id every kQueryRetrySeconds until answered, so a
    // datagram lost (or sent before the server listens) costs half a second, not the timeout.
    std::optional<cyclopt_lcm::query_reply_t> answer;
    for (auto left = deadline - Clock::now(); !answer && left > std::chrono::milliseconds(1); left = deadline - Clock::now()) {
      bus_.publish(channels::kQuery, msg, key_ ? &key_->keys[0] : nullptr);
      answer = await(replies_, msg.request_id, std::min(kQueryRetrySeconds, std::chrono::duration<double>(left).count()));
    }
    awaiting_.erase(msg.request_id);
    if (!answer) return std::nullopt;
    const cyclopt_lcm::query_reply_t& reply = *answer;
    if (!reply.error.empty()) throw QueryError(reply.error);
    all.total = reply.total;
    if (reply.row_bytes > 0) {
      if (reply.part_offset != msg.part_offset || reply.offset != msg.offset ||
          row_text.size() + reply.rows_json.size() > static_cast<std::size_t>(reply.row_bytes))
        throw QueryError("server sent part " + std::to_string(reply.part_offset) + " of row " +
                         std::to_string(reply.offset) + " where part " + std::to_string(msg.part_offset) + " of row " +
                         std::to_string(msg.offset) + " was asked for");
      row_text += reply.rows_json;
      if (row_text.size() < static_cast<std::size_t>(reply.row_bytes)) continue;
      all.rows.push_back(nlohmann::json::parse(row_text));
      row_text.clear();
    } else {
      for (auto& row : nlohmann::json::parse(reply.rows_json)) all.rows.push_back(std::move(row));
    }
    remaining -= reply.row_count;
    if (reply.next_offset < 0 || remaining <= 0) return all;
    request.offset = reply.next_offset;
  }
}

std::optional<cyclopt_lcm::job_done_t> ServiceClient::watch(
    std::int64_t job_id, const std::function<void(const cyclopt_lcm::job_progress_t&)>& on_progress,
    double timeout_seconds, double poll_seconds) {
  watched_job_ = job_id;
  progress_callback_ = &on_progress;
  const auto deadline = Clock::now() + seconds(timeout_seconds);
  std::optional<cyclopt_lcm::job_done_t> result;
  while (!result && Clock::now() < deadline) {
    const double left = std::chrono::duration<double>(deadline - Clock::now()).count();
    if (pump_until([&] { return done_.count(job_id) > 0; }, std::min(poll_seconds, left))) {
      result = done_[job_id];
      done_.erase(job_id);
      break;
    }
    const auto page = query(storage::query_for("job", job_id), std::min(poll_seconds, left));
    if (!page || page->rows.empty()) continue;
    const nlohmann::json& j = page->rows[0];
    const auto state = storage::job_state_from_string(j["state"].get<std::string>());
    if (state && storage::is_final(*state)) {
      cyclopt_lcm::job_done_t d;
      d.job_id = job_id;
      d.request_id = j["request_id"];
      d.state = j["state"];
      d.points_stored = j["points_stored"];
      d.run_seconds = j["run_seconds"];
      d.publish_seconds = j["publish_seconds"];
      d.error = j["error"];
      d.points_expected = j["points_total"].is_number() ? j["points_total"].get<int>() : -1;
      d.points_converged = j["points_converged"].is_number() ? j["points_converged"].get<int>() : -1;
      result = d;
    }
  }
  progress_callback_ = nullptr;
  watched_job_ = -1;
  return result;
}

void ServiceClient::listen(const std::function<void(const cyclopt_lcm::job_progress_t&)>& on_progress, double seconds) {
  watched_job_ = kEveryJob;
  progress_callback_ = &on_progress;
  pump_until([] { return false; }, seconds);
  progress_callback_ = nullptr;
  watched_job_ = -1;
}

std::optional<cyclopt_lcm::job_ack_t> ServiceClient::send_raw(const std::string& channel, const std::string& bytes,
                                                              const std::string& reply_id, double timeout_seconds) {
  awaiting_.insert(reply_id);
  bus_.publish(channel, wire::as_bytes(bytes));
  std::optional<cyclopt_lcm::job_ack_t> ack;
  try {
    ack = await(acks_, reply_id, timeout_seconds);
  } catch (const SignatureRejected& e) {
    ack = cyclopt_lcm::job_ack_t{reply_id, false, -1, false, "", "signature", e.what()};
  }
  awaiting_.erase(reply_id);
  return ack;
}

}  // namespace cyclopt::client
