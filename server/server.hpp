#pragma once
// The whole server on a caller-supplied LCM instance: opens the store (re-queueing interrupted
// jobs), starts the workers and answers requests. serve() pumps LCM until `stop` is set; tests
// on memq:// may instead pump the shared LCM instance themselves.

#include "cyclopt/service/job_kind.hpp"
#include "cyclopt/storage/result_store.hpp"
#include "job_executor.hpp"
#include "lcm_publisher.hpp"
#include "request_handler.hpp"
#include "server_config.hpp"
#include "worker_pool.hpp"

#include <lcm/lcm-cpp.hpp>

#include <atomic>
#include <memory>

namespace cyclopt::server {

class Server {
 public:
  Server(const ServerConfig& config, const service::JobKindRegistry& kinds, lcm::LCM& lcm);
  ~Server();  // stops workers (checkpointing their jobs), then closes the database

  void serve(const std::atomic<bool>& stop);
  const storage::RecoverySummary& recovery() const { return recovery_; }
  const RequestCounters& counters() const { return handler_.counters(); }
  storage::ResultStore& store() { return store_; }

 private:
  ServerConfig config_;
  lcm::LCM& lcm_;
  storage::ResultStore store_;
  storage::RecoverySummary recovery_;
  LcmPublisher publisher_;
  std::unique_ptr<JobExecutor> executor_;  // local threads or Slurm (config.executor)
  WorkerPool pool_;
  RequestHandler handler_;
};

}  // namespace cyclopt::server
