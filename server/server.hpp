#pragma once
// The whole server on a caller-supplied LCM instance: opens the store (re-queueing interrupted
// jobs), starts the workers and answers requests. serve() pumps LCM until `stop` is set; tests
// on memq:// may instead pump the shared LCM instance themselves. config.lcm_url must be the URL
// `lcm` was opened with (on udpm:// the server receives through its own checked receiver,
// wire::MessageBus).

#include "cyclopt/service/job_kind.hpp"
#include "cyclopt/storage/result_store.hpp"
#include "job_executor.hpp"
#include "lcm_publisher.hpp"
#include "message_bus.hpp"
#include "request_handler.hpp"
#include "server_config.hpp"
#include "worker_pool.hpp"

#include <lcm/lcm-cpp.hpp>

#include <atomic>
#include <memory>
#include <optional>

namespace cyclopt::server {

class Server {
 public:
  Server(const ServerConfig& config, const service::JobKindRegistry& kinds, lcm::LCM& lcm);
  ~Server();  // stops workers (checkpointing their jobs), then closes the database

  void serve(const std::atomic<bool>& stop);
  const storage::RecoverySummary& recovery() const { return recovery_; }
  const RequestCounters& counters() const { return handler_.counters(); }
  storage::ResultStore& store() { return store_; }
  const wire::MessageBus& bus() const { return bus_; }
  bool authenticates() const { return keys_.has_value(); }
  RequestHandler& handler() { return handler_; }

 private:
  ServerConfig config_;
  wire::MessageBus bus_;
  std::optional<wire::KeyRing> keys_;  // config.auth_secret_file, if set
  storage::ResultStore store_;
  storage::RecoverySummary recovery_;
  std::optional<JobOwners> owners_;
  LcmPublisher publisher_;
  std::unique_ptr<JobExecutor> executor_;  // local threads or Slurm (config.executor)
  WorkerPool pool_;
  RequestHandler handler_;
};

}  // namespace cyclopt::server
