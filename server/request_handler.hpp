#pragma once
// Answers every message on CYCLOPT_SUBMIT, CYCLOPT_CANCEL and CYCLOPT_QUERY. Nothing a client
// sends can crash the server: every payload is checked against its type's wire layout before it
// is decoded (wire::decode_checked), and undecodable bytes, malformed JSON, wrong types,
// out-of-range or oversize values are each answered by a job_ack_t rejection whose field and
// problem name what was wrong (query errors arrive as a query_reply_t with error set). A result
// row too large for one reply is sent in parts (query_reply_t.row_bytes). With a key ring
// (message_auth.hpp) every request must be signed by a known key within the clock skew, else it
// is rejected (field "signature") and counted; answers are signed with the requester's key, and
// a job may be cancelled only by its submitter's key or an admin key. A valid job whose
// estimated cost exceeds the server's limits, or whose sender's queue quota is used up, is
// rejected too (field: the spec field driving the cost, or "queue"); the sender is the signing
// key, or for unauthenticated clients the sending host (MessageBus::current_source). Under
// authentication a key reads only its own jobs unless it is an admin key or auth_reads is "any",
// and a request whose signature is not accepted gets the fixed unsigned
// channels::kSignatureRejected.

#include "cyclopt/service/job_kind.hpp"
#include "cyclopt/storage/result_store.hpp"
#include "job_owners.hpp"
#include "lcm_publisher.hpp"
#include "message_bus.hpp"
#include "server_config.hpp"
#include "worker_pool.hpp"

#include <atomic>
#include <optional>
#include <span>

namespace cyclopt::server {

// Counters for the log and the tests.
struct RequestCounters {
  std::atomic<long> accepted{0};
  std::atomic<long> duplicates{0};
  std::atomic<long> rejected{0};
  std::atomic<long> queries{0};
  std::atomic<long> unauthenticated{0};  // unsigned, unknown-key, forged or stale requests
  std::atomic<double> submit_seconds{0.0};  // wall time spent handling submissions (decode .. ack)
};

class RequestHandler {
 public:
  // keys, owners: nullptr when messages are not authenticated.
  RequestHandler(const ServerConfig& config, const service::JobKindRegistry& kinds, storage::ResultStore& store,
                 LcmPublisher& publisher, WorkerPool& pool, const wire::KeyRing* keys, JobOwners* owners);
  void subscribe(wire::MessageBus& bus);
  const RequestCounters& counters() const { return counters_; }

  // The handlers of the three channels (public for the fuzz test, which calls them directly).
  void on_submit(std::span<const std::uint8_t> payload);
  void on_cancel(std::span<const std::uint8_t> payload);
  void on_query(std::span<const std::uint8_t> payload);

 private:
  void handle_submit(std::span<const std::uint8_t> payload);
  // Decodes a request of type T (signature trailer split off and checked); nullopt after a
  // rejection. `key` is the signing key (nullptr when authentication is off).
  template <class T>
  std::optional<T> receive(std::span<const std::uint8_t> raw, const char* channel, const wire::AuthKey*& key);
  void accept(const std::string& request_id, std::int64_t job_id, bool duplicate, const std::string& state,
              const wire::AuthKey* key);
  void reject(const std::string& request_id, const std::string& field, const std::string& problem,
              const wire::AuthKey* key = nullptr);

  const ServerConfig& config_;
  const service::JobKindRegistry& kinds_;
  storage::ResultStore& store_;
  LcmPublisher& publisher_;
  WorkerPool& pool_;
  const wire::KeyRing* keys_;
  JobOwners* owners_;
  const wire::MessageBus* bus_ = nullptr;  // subscribe()'s: the source of the message in hand
  RequestCounters counters_;
  // The last row sent in parts, serialised, so that each part does not serialise it again.
  struct PartedRow {
    std::string what, state;
    std::int64_t job_id = -1;
    int offset = -1;
    std::string text;
  } parted_;
};

}  // namespace cyclopt::server
