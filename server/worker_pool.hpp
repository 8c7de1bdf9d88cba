#pragma once
// One thread per worker. Each claims the oldest queued job from the store, runs it through the
// executor (job_executor.hpp: on this thread, or on Slurm) with a WorkerJobContext and records
// the outcome: done, incomplete or failed as judged from its required points (storage/job_outcome.hpp),
// failed (exception or limit), cancelled, or back to queued when the server
// shuts down or a point could not be stored (a full disk): its stored points are kept and it
// resumes later; its watchers get a job_done_t with state "queued" saying why. After a storage
// failure no job is claimed for kStoreFailurePause.
//
// No job is `running` without a worker: a state change the store refuses (a full disk) is retried
// with back-off (kFirstRetry doubling up to kMaxRetry) until the store accepts it, and the server's
// log and a progress message say so; only a shutdown ends the retries (the next start re-queues
// the job). Every kOrphanCheckPeriod a watchdog re-queues any `running` job that no worker of this
// pool holds (the server's start does the same, ResultStore::recover_interrupted).
//
// A job's spec is parsed once: submit() keeps the submission's parsed spec for the worker that
// claims the job. A job without one (queued before this server started) is parsed from its stored
// text when claimed; if that text no longer validates (a database edited by hand, or written by a
// server whose kinds accepted it), the job fails with a message naming the field.

#include "job_executor.hpp"
#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/storage/job_outcome.hpp"
#include "cyclopt/storage/result_store.hpp"
#include "lcm_publisher.hpp"
#include "server_config.hpp"
#include "worker_job_context.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

namespace cyclopt::server {

class WorkerPool {
 public:
  WorkerPool(const ServerConfig& config, const service::JobKindRegistry& kinds, const JobExecutor& executor,
             storage::ResultStore& store, LcmPublisher& publisher);
  ~WorkerPool();  // stop() and join

  // Queues a validated submission (storage::ResultStore::submit) with its parsed spec, which the
  // worker that claims the new job runs.
  storage::SubmitOutcome submit(const storage::Submission& submission, const storage::SenderQuota& quota,
                                std::shared_ptr<const service::ValidatedJobSpec> spec);
  void wake();                          // a job was queued
  void cancel(std::int64_t job_id);     // raises the flag of a running job
  void stop();                          // running jobs checkpoint and return to the queue

 private:
  struct Claimed {
    storage::JobRecord job;
    std::shared_ptr<const service::ValidatedJobSpec> spec;  // null: parse job.spec_json
  };
  std::optional<Claimed> claim();
  void work();
  void run_job(const storage::JobRecord& job, std::shared_ptr<const service::ValidatedJobSpec> spec);
  void requeue_after_store_failure(const storage::JobRecord& job, WorkerJobContext& ctx);
  // Runs `write` (a state change of `job`) until the store accepts it; false: shutdown came first.
  bool record_state(const storage::JobRecord& job, WorkerJobContext& ctx, const std::function<void()>& write);
  void release(std::int64_t job_id);  // its worker is done with the job
  void watch_for_orphans();
  void requeue_orphans();
  void publish_done(const storage::JobRecord& job, WorkerJobContext& ctx, storage::JobState state,
                    const std::string& error, const std::optional<storage::JobOutcome>& outcome = std::nullopt);
  void pause_claims();
  bool claims_paused();

  static constexpr std::chrono::seconds kStoreFailurePause{5};
  static constexpr std::chrono::milliseconds kFirstRetry{250};
  static constexpr std::chrono::milliseconds kMaxRetry{2000};
  static constexpr std::chrono::seconds kOrphanCheckPeriod{2};

  const ServerConfig& config_;
  const service::JobKindRegistry& kinds_;
  const JobExecutor& executor_;
  storage::ResultStore& store_;
  LcmPublisher& publisher_;
  std::atomic<bool> shutdown_{false};
  std::mutex mutex_;
  std::condition_variable wake_;
  std::map<std::int64_t, std::shared_ptr<std::atomic<bool>>> cancel_flags_;  // running jobs
  std::set<std::int64_t> early_cancels_;  // cancelled after being claimed, before their flag existed
  // Held while a job is added to the queue with its spec and while one is claimed with it, so a
  // worker never claims a submission before its parsed spec is here.
  std::mutex queue_mutex_;
  std::map<std::int64_t, std::shared_ptr<const service::ValidatedJobSpec>> parsed_;  // queued jobs
  std::set<std::int64_t> live_;  // claimed by a worker whose final state change is not yet recorded
  std::chrono::steady_clock::time_point claims_paused_until_{};
  std::vector<std::thread> threads_;
  std::thread watchdog_;
};

}  // namespace cyclopt::server
