#include "request_handler.hpp"

#include <cyclopt_lcm/job_ack_t.hpp>
#include <cyclopt_lcm/job_cancel_t.hpp>
#include <cyclopt_lcm/job_submit_t.hpp>
#include <cyclopt_lcm/query_reply_t.hpp>
#include <cyclopt_lcm/query_request_t.hpp>

#include "cyclopt/cli/version.hpp"
#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/resolved_spec.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/jobs/foot/stored_foot_fit.hpp"
#include "cyclopt/jobs/walker/stored_start.hpp"
#include "cyclopt/storage_read/result_queries.hpp"
#include "cyclopt_channels.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace cyclopt::server {

namespace {

// A too-long request id is still echoed (up to this length) so its sender sees the rejection.
constexpr std::size_t kMaxEchoedRequestIdBytes = 1024;
constexpr int kRowsPerReply = 32;

std::string undecodable(const char* channel, const std::string& problem) {
  return std::string(channel) + ": undecodable message: " + problem;
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
                               storage::ResultStore& store, LcmPublisher& publisher, WorkerPool& pool,
                               const wire::KeyRing* keys, JobOwners* owners)
    : config_(config), kinds_(kinds), store_(store), publisher_(publisher), pool_(pool), keys_(keys), owners_(owners) {}

template <class T>
std::optional<T> RequestHandler::receive(std::span<const std::uint8_t> raw, const char* channel,
                                         const wire::AuthKey*& key) {
  key = nullptr;
  const std::optional<wire::Signature> sig = wire::split_signature(raw);
  std::string problem;
  auto msg = wire::decode_checked<T>(raw, problem);
  if (!msg) {
    reject("", channel, undecodable(channel, problem));
    return std::nullopt;
  }
  if (!keys_) return msg;
  key = wire::verify_signature(*keys_, sig, channel, raw, msg->request_id, wire::unix_now_us(), problem);
  if (key) return msg;
  ++counters_.unauthenticated;
  reject(msg->request_id, "signature", channels::kSignatureRejected);  // fixed and unsigned: nothing to learn from it
  return std::nullopt;
}

void RequestHandler::subscribe(wire::MessageBus& bus) {
  bus_ = &bus;
  bus.subscribe(channels::kSubmit, [this](std::span<const std::uint8_t> p) { on_submit(p); });
  bus.subscribe(channels::kCancel, [this](std::span<const std::uint8_t> p) { on_cancel(p); });
  bus.subscribe(channels::kQuery, [this](std::span<const std::uint8_t> p) { on_query(p); });
}

void RequestHandler::reject(const std::string& request_id, const std::string& field, const std::string& problem,
                            const wire::AuthKey* key) {
  ++counters_.rejected;
  cyclopt_lcm::job_ack_t ack;
  ack.request_id = request_id.substr(0, kMaxEchoedRequestIdBytes);
  ack.accepted = false;
  ack.job_id = -1;
  ack.duplicate = false;
  ack.field = field;
  ack.problem = problem.substr(0, 2000);
  publisher_.publish_signed(channels::kAck, ack, key);
}

void RequestHandler::accept(const std::string& request_id, std::int64_t job_id, bool duplicate,
                            const std::string& state, const wire::AuthKey* key) {
  cyclopt_lcm::job_ack_t ack;
  ack.request_id = request_id;
  ack.accepted = true;
  ack.job_id = job_id;
  ack.duplicate = duplicate;
  ack.state = state;
  publisher_.publish_signed(channels::kAck, ack, key);
}

void RequestHandler::on_submit(std::span<const std::uint8_t> payload) {
  const auto t0 = std::chrono::steady_clock::now();
  handle_submit(payload);
  counters_.submit_seconds =
      counters_.submit_seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void RequestHandler::handle_submit(std::span<const std::uint8_t> payload) {
  const wire::AuthKey* key = nullptr;
  const auto decoded = receive<cyclopt_lcm::job_submit_t>(payload, channels::kSubmit, key);
  if (!decoded) return;
  const cyclopt_lcm::job_submit_t& msg = *decoded;
  try {
    if (const std::string p = request_id_problem(msg.request_id); !p.empty())
      return reject(msg.request_id, "request_id", "request_id: " + p, key);
    if (msg.spec_json.size() > channels::kMaxSpecBytes)
      return reject(msg.request_id, "spec_json",
                    "spec_json: oversize, " + std::to_string(msg.spec_json.size()) + " bytes, at most " +
                        std::to_string(channels::kMaxSpecBytes) + " allowed",
                    key);
    // A foot naming a stored fit becomes the fitted foot and a start naming a stored point that
    // point's x here, once (stored_foot_fit.hpp, stored_start.hpp).
    const nlohmann::json spec = jobs::with_stored_start(
        jobs::with_stored_foot_fit(service::parse_job_spec_text(msg.spec_json), store_), store_);
    auto v = std::make_shared<const service::ValidatedJobSpec>(service::validate_job_spec(spec, kinds_));
    const service::JobCost cost = v->estimate();
    service::check_cost(cost, {config_.caps.max_wall_seconds, config_.max_job_memory_mb * (1 << 20)});
    // The quota's sender: the key, or for an unauthenticated client its host (the datagram's source
    // address, which the server's own udpm receiver reads); one shared pool only where the provider
    // gives no address (memq://, file://).
    const std::string host = bus_ ? bus_->current_source() : "";
    const std::string sender = key ? key->id : host.empty() ? "" : "host " + host;
    const nlohmann::json resolved = service::resolved_spec(*v);
    // The parsed spec goes to the worker with the job: it is not parsed again.
    const storage::SubmitOutcome out = pool_.submit({msg.request_id, v->scene, v->task, msg.spec_json, sender,
                                                     cost.seconds, cli::git_revision(),
                                                     service::random_seeds(resolved).dump(), resolved.dump(),
                                                     cli::build_arch(), cli::build_flags()},
                                                    config_.quota, v);
    if (out.over_quota)
      return reject(msg.request_id, "queue",
                    "queue: sender '" + sender + "' has " + std::to_string(out.queued_jobs) + " queued jobs estimated at " +
                        service::duration_text(out.queued_seconds) + "; with this one (" +
                        service::duration_text(cost.seconds) + ") that exceeds the quota of " +
                        std::to_string(config_.quota.max_queued_jobs) + " jobs or " +
                        service::duration_text(config_.quota.max_queued_seconds) +
                        " per sender (cycloptd --max-queued-jobs, --max-queued-hours); resubmit when some have run",
                    key);
    if (out.spec_differs)
      return reject(msg.request_id, "request_id",
                    "request_id: already used by job " + std::to_string(out.job_id) + " with a different spec", key);
    if (!out.duplicate && key) owners_->record(out.job_id, *key);
    ++(out.duplicate ? counters_.duplicates : counters_.accepted);
    accept(msg.request_id, out.job_id, out.duplicate, std::string(storage::to_string(out.state)), key);
    if (!out.duplicate) pool_.wake();
  } catch (const SpecError& e) {
    reject(msg.request_id, e.field(), e.what(), key);
  } catch (const storage::StorageError& e) {  // a full disk, say: the spec may be fine
    reject(msg.request_id, "server",
           std::string("server: the results database refused the job (") + e.what() +
               "): nothing was queued; submit again later (the same request id is safe)",
           key);
  } catch (const std::exception& e) {
    reject(msg.request_id, "server", std::string("server: internal error: ") + e.what(), key);
  } catch (...) {
    reject(msg.request_id, "server", "server: internal error", key);
  }
}

void RequestHandler::on_cancel(std::span<const std::uint8_t> payload) {
  const wire::AuthKey* key = nullptr;
  const auto decoded = receive<cyclopt_lcm::job_cancel_t>(payload, channels::kCancel, key);
  if (!decoded) return;
  const cyclopt_lcm::job_cancel_t& msg = *decoded;
  try {
    if (key && !key->admin) {
      const wire::AuthKey* owner = owners_->owner(msg.job_id);
      if (owner != key && store_.job(msg.job_id))
        return reject(msg.request_id, "job_id",
                      "job_id: job " + std::to_string(msg.job_id) + " was not submitted with key '" + key->id +
                          "'; only its submitter's key or an admin key may cancel it",
                      key);
    }
    const storage::CancelOutcome out = store_.cancel(msg.job_id);
    if (out == storage::CancelOutcome::not_found)
      return reject(msg.request_id, "job_id", "job_id: no job " + std::to_string(msg.job_id), key);
    if (out == storage::CancelOutcome::already_final)
      return reject(msg.request_id, "job_id", "job_id: job " + std::to_string(msg.job_id) + " has already finished", key);
    pool_.cancel(msg.job_id);
    accept(msg.request_id, msg.job_id, false, out == storage::CancelOutcome::cancelled ? "cancelled" : "running", key);
  } catch (const std::exception& e) {
    reject(msg.request_id, "server", std::string("server: internal error: ") + e.what(), key);
  } catch (...) {
    reject(msg.request_id, "server", "server: internal error", key);
  }
}

void RequestHandler::on_query(std::span<const std::uint8_t> payload) {
  const wire::AuthKey* key = nullptr;
  const auto decoded = receive<cyclopt_lcm::query_request_t>(payload, channels::kQuery, key);
  if (!decoded) return;
  const cyclopt_lcm::query_request_t& msg = *decoded;
  ++counters_.queries;
  // Under authentication a key reads its own jobs, an admin key every job (auth_reads "owner"),
  // unless the server lets every key read every job (auth_reads "any").
  const bool own_jobs_only = key && !key->admin && config_.auth_reads == AuthReads::owner;
  cyclopt_lcm::query_reply_t reply;
  reply.request_id = msg.request_id.substr(0, kMaxEchoedRequestIdBytes);
  reply.offset = msg.offset;
  reply.row_count = 0;
  reply.total = 0;
  reply.next_offset = -1;
  reply.rows_json = "[]";
  reply.row_bytes = 0;
  reply.part_offset = 0;
  try {
    if (msg.part_offset < 0) throw std::invalid_argument("part_offset: must be >= 0, got " + std::to_string(msg.part_offset));
    const bool cached = msg.part_offset > 0 && parted_.what == msg.what && parted_.job_id == msg.job_id &&
                        parted_.state == msg.state && parted_.offset == msg.offset;
    // At most kRowsPerReply rows are read: a reply carries 48 KiB, and result rows can be large.
    storage::QueryRequest request{msg.what, msg.job_id, msg.state, msg.offset,
                                  std::min(msg.limit, cached ? 1 : kRowsPerReply), std::nullopt};
    if (own_jobs_only && msg.what == "jobs") request.sender = key->id;
    if (own_jobs_only && msg.what != "jobs" && owners_->owner(msg.job_id) != key && store_.job(msg.job_id))
      throw std::invalid_argument("job_id: job " + std::to_string(msg.job_id) + " was not submitted with key '" + key->id +
                                  "'; only its submitter's key or an admin key may read it");
    const storage::QueryPage page = storage::run_query(store_, request);
    reply.total = page.total;
    // Rows as ASCII text (non-ASCII escaped), so that a row can be cut into parts at any byte.
    std::string rows = "[";
    int n = 0;
    bool parted = cached;
    for (const auto& row : page.rows) {
      if (cached) break;
      std::string text = row.dump(-1, ' ', true);
      if (n == 0 && (msg.part_offset > 0 || text.size() + 2 > channels::kMaxQueryReplyRowBytes)) {
        parted_ = {msg.what, msg.state, msg.job_id, msg.offset, std::move(text)};
        parted = true;
        break;
      }
      if (rows.size() + text.size() + 2 > channels::kMaxQueryReplyRowBytes) break;
      rows += (n ? "," : "") + text;
      ++n;
    }
    if (parted) {
      // Row `offset` alone is too large for a reply: send the part of it that starts at part_offset.
      const std::string& text = parted_.text;
      if (static_cast<std::size_t>(msg.part_offset) >= text.size())
        throw std::invalid_argument("part_offset: row " + std::to_string(msg.offset) + " has " +
                                    std::to_string(text.size()) + " bytes, got " + std::to_string(msg.part_offset));
      reply.rows_json = text.substr(static_cast<std::size_t>(msg.part_offset), channels::kMaxQueryReplyRowBytes);
      reply.row_bytes = static_cast<int>(text.size());
      reply.part_offset = msg.part_offset;
      const bool last = msg.part_offset + reply.rows_json.size() == text.size();
      reply.row_count = last ? 1 : 0;
      reply.next_offset = !last ? msg.offset : msg.offset + 1 < page.total ? msg.offset + 1 : -1;
    } else if (msg.part_offset > 0) {
      throw std::invalid_argument("part_offset: there is no row " + std::to_string(msg.offset));
    } else {
      reply.rows_json = rows + "]";
      reply.row_count = n;
      const int next = msg.offset + n;
      reply.next_offset = next < page.total && n > 0 ? next : -1;
    }
  } catch (const std::exception& e) {
    reply.rows_json = "[]";
    reply.row_count = 0;
    reply.row_bytes = 0;
    reply.error = e.what();
  } catch (...) {
    reply.error = "server: internal error";
  }
  publisher_.publish_signed(channels::kQueryReply, reply, key);
}

}  // namespace cyclopt::server
