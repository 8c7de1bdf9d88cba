#pragma once
// Answers every message on CYCLOPT_SUBMIT, CYCLOPT_CANCEL and CYCLOPT_QUERY. Nothing a client
// sends can crash the server: undecodable bytes, malformed JSON, wrong types, out-of-range or
// oversize values are each answered by a job_ack_t rejection whose field and problem name
// what was wrong (query errors arrive as a query_reply_t with error set). A valid job whose
// estimated cost exceeds the server's limits, or whose sender's queue quota is used up, is
// rejected too (field: the spec field driving the cost, or "queue").

#include "cyclopt/service/job_kind.hpp"
#include "cyclopt/storage/result_store.hpp"
#include "lcm_publisher.hpp"
#include "server_config.hpp"
#include "worker_pool.hpp"

#include <lcm/lcm-cpp.hpp>

#include <atomic>

namespace cyclopt::server {

// Counters for the log and the tests.
struct RequestCounters {
  std::atomic<long> accepted{0};
  std::atomic<long> duplicates{0};
  std::atomic<long> rejected{0};
  std::atomic<long> queries{0};
  std::atomic<double> submit_seconds{0.0};  // wall time spent handling submissions (decode .. ack)
};

class RequestHandler {
 public:
  RequestHandler(const ServerConfig& config, const service::JobKindRegistry& kinds, storage::ResultStore& store,
                 LcmPublisher& publisher, WorkerPool& pool);
  void subscribe(lcm::LCM& lcm);
  const RequestCounters& counters() const { return counters_; }

  void on_submit(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void on_cancel(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void on_query(const lcm::ReceiveBuffer* rbuf, const std::string& channel);

 private:
  void handle_submit(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void accept(const std::string& request_id, std::int64_t job_id, bool duplicate, const std::string& state);
  void reject(const std::string& request_id, const std::string& field, const std::string& problem);

  const ServerConfig& config_;
  const service::JobKindRegistry& kinds_;
  storage::ResultStore& store_;
  LcmPublisher& publisher_;
  WorkerPool& pool_;
  RequestCounters counters_;
};

}  // namespace cyclopt::server
