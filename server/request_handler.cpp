#include "request_handler.hpp"

#include <cyclopt_lcm/job_ack_t.hpp>
#include <cyclopt_lcm/job_cancel_t.hpp>
#include <cyclopt_lcm/job_submit_t.hpp>
#include <cyclopt_lcm/query_reply_t.hpp>
#include <cyclopt_lcm/query_request_t.hpp>

#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/storage/result_queries.hpp"
#include "cyclopt_channels.hpp"

#include <chrono>
#include <cstdio>

namespace cyclopt::server {

namespace {

// A too-long request id is still echoed (up to this length) so its sender sees the rejection.
constexpr std::size_t kMaxEchoedRequestIdBytes = 1024;

// Decodes a message of type T, or returns false.
template <class T>
bool decode(const lcm::ReceiveBuffer* rbuf, T& msg) {
  return rbuf->data_size > 0 && rbuf->data_size < (1u << 30) &&
         msg.decode(rbuf->data, 0, static_cast<int>(rbuf->data_size)) >= 0;
}

std::string undecodable(const std::string& channel, const lcm::ReceiveBuffer* rbuf, const char* type) {
  return std::string(channel) + ": undecodable message of " + std::to_string(rbuf->data_size) + " bytes: not a cyclopt_lcm." + type +
         " (wrong type fingerprint or truncated)";
}

// Checks a client request id; returns the problem or "".
std::string request_id_problem(const std::string& id) {
  if (id.empty()) return "must not be empty";
  if (id.size() > channels::kMaxRequestIdBytes)
    return "must be at most " + std::to_string(channels::kMaxRequestIdBytes) + " characters, got " + std::to_string(id.size());
  for (unsigned char c : id)
    if (c < 0x21 || c > 0x7e) return "must consist of printable ASCII characters without spaces";
  return "";
}

}  // namespace

RequestHandler::RequestHandler(const ServerConfig& config, const service::JobKindRegistry& kinds,
                               storage::ResultStore& store, LcmPublisher& publisher, WorkerPool& pool)
    : config_(config), kinds_(kinds), store_(store), publisher_(publisher), pool_(pool) {}

void RequestHandler::subscribe(lcm::LCM& lcm) {
  lcm.subscribe(channels::kSubmit, &RequestHandler::on_submit, this);
  lcm.subscribe(channels::kCancel, &RequestHandler::on_cancel, this);
  lcm.subscribe(channels::kQuery, &RequestHandler::on_query, this);
}

void RequestHandler::reject(const std::string& request_id, const std::string& field, const std::string& problem) {
  ++counters_.rejected;
  cyclopt_lcm::job_ack_t ack;
  ack.request_id = request_id.substr(0, kMaxEchoedRequestIdBytes);
  ack.accepted = false;
  ack.job_id = -1;
  ack.duplicate = false;
  ack.field = field;
  ack.problem = problem.substr(0, 2000);
  publisher_.publish(channels::kAck, ack);
}

void RequestHandler::accept(const std::string& request_id, std::int64_t job_id, bool duplicate,
                            const std::string& state) {
  cyclopt_lcm::job_ack_t ack;
  ack.request_id = request_id;
  ack.accepted = true;
  ack.job_id = job_id;
  ack.duplicate = duplicate;
  ack.state = state;
  publisher_.publish(channels::kAck, ack);
}

void RequestHandler::on_submit(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  const auto t0 = std::chrono::steady_clock::now();
  handle_submit(rbuf, channel);
  counters_.submit_seconds =
      counters_.submit_seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void RequestHandler::handle_submit(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  cyclopt_lcm::job_submit_t msg;
  if (!decode(rbuf, msg)) return reject("", channel, undecodable(channel, rbuf, "job_submit_t"));
  try {
    if (const std::string p = request_id_problem(msg.request_id); !p.empty())
      return reject(msg.request_id, "request_id", "request_id: " + p);
    if (msg.spec_json.size() > channels::kMaxSpecBytes)
      return reject(msg.request_id, "spec_json",
                    "spec_json: oversize, " + std::to_string(msg.spec_json.size()) + " bytes, at most " +
                        std::to_string(channels::kMaxSpecBytes) + " allowed");
    const service::ValidatedJobSpec v = service::validate_job_spec(service::parse_job_spec_text(msg.spec_json), kinds_);
    const service::JobCost cost = v.kind->estimate ? v.kind->estimate(v.spec) : service::JobCost{};
    service::check_cost(cost, {config_.caps.max_wall_seconds, config_.max_job_memory_mb * (1 << 20)});
    const std::string sender;  // every client is anonymous until messages are authenticated
    const storage::SubmitOutcome out =
        store_.submit({msg.request_id, v.scene, v.task, msg.spec_json, sender, cost.seconds}, config_.quota);
    if (out.over_quota)
      return reject(msg.request_id, "queue",
                    "queue: sender '" + sender + "' has " + std::to_string(out.queued_jobs) + " queued jobs estimated at " +
                        service::duration_text(out.queued_seconds) + "; with this one (" +
                        service::duration_text(cost.seconds) + ") that exceeds the quota of " +
                        std::to_string(config_.quota.max_queued_jobs) + " jobs or " +
                        service::duration_text(config_.quota.max_queued_seconds) +
                        " per sender (cycloptd --max-queued-jobs, --max-queued-hours); resubmit when some have run");
    if (out.spec_differs)
      return reject(msg.request_id, "request_id",
                    "request_id: already used by job " + std::to_string(out.job_id) + " with a different spec");
    ++(out.duplicate ? counters_.duplicates : counters_.accepted);
    accept(msg.request_id, out.job_id, out.duplicate, std::string(storage::to_string(out.state)));
    if (!out.duplicate) pool_.wake();
  } catch (const service::SpecError& e) {
    reject(msg.request_id, e.field(), e.what());
  } catch (const std::exception& e) {
    reject(msg.request_id, "server", std::string("server: internal error: ") + e.what());
  } catch (...) {
    reject(msg.request_id, "server", "server: internal error");
  }
}

void RequestHandler::on_cancel(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  cyclopt_lcm::job_cancel_t msg;
  if (!decode(rbuf, msg)) return reject("", channel, undecodable(channel, rbuf, "job_cancel_t"));
  try {
    const storage::CancelOutcome out = store_.cancel(msg.job_id);
    if (out == storage::CancelOutcome::not_found)
      return reject(msg.request_id, "job_id", "job_id: no job " + std::to_string(msg.job_id));
    if (out == storage::CancelOutcome::already_final)
      return reject(msg.request_id, "job_id", "job_id: job " + std::to_string(msg.job_id) + " has already finished");
    pool_.cancel(msg.job_id);
    accept(msg.request_id, msg.job_id, false, out == storage::CancelOutcome::cancelled ? "cancelled" : "running");
  } catch (const std::exception& e) {
    reject(msg.request_id, "server", std::string("server: internal error: ") + e.what());
  } catch (...) {
    reject(msg.request_id, "server", "server: internal error");
  }
}

void RequestHandler::on_query(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  cyclopt_lcm::query_request_t msg;
  if (!decode(rbuf, msg)) return reject("", channel, undecodable(channel, rbuf, "query_request_t"));
  ++counters_.queries;
  cyclopt_lcm::query_reply_t reply;
  reply.request_id = msg.request_id.substr(0, kMaxEchoedRequestIdBytes);
  reply.offset = msg.offset;
  reply.row_count = 0;
  reply.total = 0;
  reply.next_offset = -1;
  reply.rows_json = "[]";
  try {
    const storage::QueryPage page =
        storage::run_query(store_, {msg.what, msg.job_id, msg.state, msg.offset, msg.limit});
    // Cut the page so the message stays below kMaxQueryReplyRowBytes.
    std::string rows = "[";
    int n = 0;
    for (const auto& row : page.rows) {
      const std::string text = row.dump();
      if (text.size() + 2 > channels::kMaxQueryReplyRowBytes)
        throw std::length_error("row " + std::to_string(msg.offset + n) + " is " + std::to_string(text.size()) +
                                " bytes, more than a reply can carry; read it with --db");
      if (rows.size() + text.size() + 2 > channels::kMaxQueryReplyRowBytes) break;
      rows += (n ? "," : "") + text;
      ++n;
    }
    reply.rows_json = rows + "]";
    reply.row_count = n;
    reply.total = page.total;
    const int next = msg.offset + n;
    reply.next_offset = next < page.total && n > 0 ? next : -1;
  } catch (const std::exception& e) {
    reply.error = e.what();
  } catch (...) {
    reply.error = "server: internal error";
  }
  publisher_.publish(channels::kQueryReply, reply);
}

}  // namespace cyclopt::server
