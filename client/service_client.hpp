#pragma once
// Client side of the LCM protocol (proto/lcm, cyclopt_channels.hpp): submissions retried until
// acknowledged, cancellation, paged queries (rows too large for one reply are fetched in parts)
// and progress watching. Works on any LCM instance, including a memq:// one shared with an
// in-process server (the waits pump that instance). Every received payload is checked against
// its type's wire layout before it is decoded (wire::decode_checked); malformed ones are counted
// and ignored.

#include <cyclopt_lcm/job_ack_t.hpp>
#include <cyclopt_lcm/job_done_t.hpp>
#include <cyclopt_lcm/job_progress_t.hpp>
#include <cyclopt_lcm/query_reply_t.hpp>

#include "cyclopt/storage_read/result_queries.hpp"
#include "message_bus.hpp"

#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace cyclopt::client {

// A fresh, random request id (32 hex digits).
std::string new_request_id();

// A query the server answered with an error (the message names the field).
class QueryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The server did not accept the request's signature (channels::kSignatureRejected): an unknown
// key, a wrong secret, or a clock more than the allowed skew away from the server's.
class SignatureRejected : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ServiceClient {
 public:
  // `url`: the one `lcm` was opened with (wire::resolved_lcm_url); udpm:// receives through the
  // checked receiver of wire::MessageBus.
  // key: with it every request is signed and only answers, progress and done messages signed
  // with it are believed (message_auth.hpp); without it signatures are ignored.
  explicit ServiceClient(lcm::LCM& lcm, const std::string& url = "", std::optional<wire::AuthKey> key = std::nullopt);
  // A monitor holding the server's key file (cyclopt-web, docs/dashboard.md): believes answers,
  // progress and done messages signed with any key of `believed`; makes no requests of its own.
  ServiceClient(lcm::LCM& lcm, const std::string& url, wire::KeyRing believed);

  // Every request below throws SignatureRejected when the server answers that it does not accept
  // the request's signature (the one answer believed unsigned, cyclopt_channels.hpp).
  // Publishes the submission every retry_seconds until an answer for request_id arrives or
  // timeout_seconds pass (nullopt). The answer may be a rejection (accepted = false).
  std::optional<cyclopt_lcm::job_ack_t> submit(const std::string& request_id, const std::string& spec_json,
                                               double timeout_seconds, double retry_seconds = 0.5);
  std::optional<cyclopt_lcm::job_ack_t> cancel(std::int64_t job_id, double timeout_seconds);
  // All pages from request.offset on; nullopt on timeout; throws QueryError.
  std::optional<storage::QueryPage> query(storage::QueryRequest request, double timeout_seconds);
  // Calls on_progress for every progress message of the job until its job_done_t arrives
  // (returned) or timeout_seconds pass. Every poll_seconds the job's state is also queried, so
  // a job that finished before watching began (or whose done message was lost) still ends the
  // watch: then a job_done_t is synthesised from the job row.
  std::optional<cyclopt_lcm::job_done_t> watch(std::int64_t job_id,
                                               const std::function<void(const cyclopt_lcm::job_progress_t&)>& on_progress,
                                               double timeout_seconds, double poll_seconds = 1.0);

  // Calls on_progress for every progress message of any job for `seconds` (cyclopt top).
  void listen(const std::function<void(const cyclopt_lcm::job_progress_t&)>& on_progress, double seconds);

  // For tests: publishes arbitrary bytes and waits for the ack with request id `reply_id` (a
  // signature rejection returned as the ack it is, not thrown).
  std::optional<cyclopt_lcm::job_ack_t> send_raw(const std::string& channel, const std::string& bytes,
                                                 const std::string& reply_id, double timeout_seconds);
  // Received payloads that were not a well-formed encoding of their channel's type.
  long malformed_received() const { return malformed_; }
  // Well-formed messages dropped because they were not signed with this client's key.
  long unverified_received() const { return unverified_; }

  // The handlers of the four channels the client reads (public for the fuzz test).
  void on_ack(std::span<const std::uint8_t> payload);
  void on_progress(std::span<const std::uint8_t> payload);
  void on_done(std::span<const std::uint8_t> payload);
  void on_query_reply(std::span<const std::uint8_t> payload);

 private:
  void subscribe();
  bool pump_until(const std::function<bool()>& done, double seconds);
  // The message in `raw` if it is well-formed (and, with a key, signed with it).
  template <class T>
  std::optional<T> checked(const char* channel, std::span<const std::uint8_t> raw);

  // Waits for the answer to `id` (answers to other clients' requests are ignored).
  template <class Reply>
  std::optional<Reply> await(std::map<std::string, Reply>& answers, const std::string& id, double seconds);

  wire::MessageBus bus_;
  std::optional<wire::KeyRing> key_;
  long malformed_ = 0;
  long unverified_ = 0;
  std::set<std::string> awaiting_;  // request ids whose answers are kept
  std::set<std::string> signature_rejected_;  // ... answered with channels::kSignatureRejected
  std::map<std::string, cyclopt_lcm::job_ack_t> acks_;
  std::map<std::int64_t, cyclopt_lcm::job_done_t> done_;
  std::map<std::string, cyclopt_lcm::query_reply_t> replies_;
  static constexpr std::int64_t kEveryJob = -2;  // watched_job_ while listening
  std::int64_t watched_job_ = -1;
  const std::function<void(const cyclopt_lcm::job_progress_t&)>* progress_callback_ = nullptr;
};

}  // namespace cyclopt::client
