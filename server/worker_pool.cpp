#include "worker_pool.hpp"

#include <cyclopt_lcm/job_done_t.hpp>

#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/service/stored_references.hpp"
#include "cyclopt_channels.hpp"
#include "worker_job_context.hpp"

#include <cstdio>

namespace cyclopt::server {

namespace {

// The spec of a job claimed without one (queued before this server started), parsed from its
// stored text; on failure null and `error` says why.
std::shared_ptr<const service::ValidatedJobSpec> parse_stored_spec(const storage::JobRecord& job,
                                                                   const service::JobKindRegistry& kinds,
                                                                   std::string& error) {
  try {
    return std::make_shared<const service::ValidatedJobSpec>(service::validate_job_spec_text(service::runnable_spec_text(job), kinds));
  } catch (const SpecError& e) {
    error = "spec_json: the stored spec of job " + std::to_string(job.id) + " is not valid on this server (" + e.what() +
            ")";
  } catch (const std::exception& e) {
    error = "spec_json: the stored spec of job " + std::to_string(job.id) + " could not be parsed: " + e.what();
  }
  return nullptr;
}

}  // namespace

WorkerPool::WorkerPool(const ServerConfig& config, const service::JobKindRegistry& kinds, const JobExecutor& executor,
                       storage::ResultStore& store, LcmPublisher& publisher)
    : config_(config), kinds_(kinds), executor_(executor), store_(store), publisher_(publisher) {
  for (int i = 0; i < effective_workers(config); ++i) threads_.emplace_back([this] { work(); });
  watchdog_ = std::thread([this] { watch_for_orphans(); });
}

WorkerPool::~WorkerPool() {
  stop();
  for (auto& t : threads_) t.join();
  watchdog_.join();
}

storage::SubmitOutcome WorkerPool::submit(const storage::Submission& submission, const storage::SenderQuota& quota,
                                          std::shared_ptr<const service::ValidatedJobSpec> spec) {
  std::lock_guard queue(queue_mutex_);
  const storage::SubmitOutcome out = store_.submit(submission, quota);
  if (!out.over_quota && !out.duplicate) parsed_[out.job_id] = std::move(spec);
  return out;
}

void WorkerPool::wake() { wake_.notify_all(); }

void WorkerPool::cancel(std::int64_t job_id) {
  {
    std::lock_guard queue(queue_mutex_);
    parsed_.erase(job_id);  // cancelled while queued: it is never claimed
  }
  std::lock_guard lock(mutex_);
  const auto it = cancel_flags_.find(job_id);
  if (it != cancel_flags_.end())
    *it->second = true;
  else
    early_cancels_.insert(job_id);  // claimed, but run_job has not registered it yet
}

bool WorkerPool::claims_paused() {
  std::lock_guard lock(mutex_);
  return std::chrono::steady_clock::now() < claims_paused_until_;
}

void WorkerPool::stop() {
  shutdown_ = true;
  wake_.notify_all();
}

std::optional<WorkerPool::Claimed> WorkerPool::claim() {
  if (claims_paused()) return std::nullopt;
  std::lock_guard queue(queue_mutex_);
  std::optional<storage::JobRecord> job = store_.claim_next();
  if (!job) return std::nullopt;
  Claimed c{std::move(*job), nullptr};
  live_.insert(c.job.id);
  if (const auto it = parsed_.find(c.job.id); it != parsed_.end()) {
    c.spec = std::move(it->second);
    parsed_.erase(it);
  }
  return c;
}

void WorkerPool::work() {
  while (!shutdown_) {
    std::optional<Claimed> claimed;
    try {
      claimed = claim();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "cycloptd: cannot claim a job: %s\n", e.what());
    }
    if (!claimed) {
      std::unique_lock lock(mutex_);
      wake_.wait_for(lock, std::chrono::milliseconds(200));
      continue;
    }
    run_job(claimed->job, std::move(claimed->spec));
    release(claimed->job.id);
  }
}

void WorkerPool::release(std::int64_t job_id) {
  std::lock_guard queue(queue_mutex_);
  live_.erase(job_id);
}

void WorkerPool::watch_for_orphans() {
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, kOrphanCheckPeriod, [this] { return shutdown_.load(); })) {
    lock.unlock();
    requeue_orphans();
    lock.lock();
  }
}

void WorkerPool::requeue_orphans() {
  storage::RecoverySummary found;
  try {
    std::lock_guard queue(queue_mutex_);  // a claim is in live_ by the time this lock is free
    found = store_.recover_interrupted(live_, "running without a worker (found by the server's periodic check)");
  } catch (const storage::StorageError&) {
    return;  // a full disk: the next check tries again
  }
  if (found.requeued + found.cancelled == 0) return;
  std::fprintf(stderr, "cycloptd: %d running job(s) without a worker re-queued, %d cancelled as requested\n",
               found.requeued, found.cancelled);
  wake_.notify_all();
}

bool WorkerPool::record_state(const storage::JobRecord& job, WorkerJobContext& ctx, const std::function<void()>& write) {
  auto wait = std::chrono::duration_cast<std::chrono::steady_clock::duration>(kFirstRetry);
  bool retrying = false;
  for (;;) {
    try {
      write();
      if (retrying) std::fprintf(stderr, "cycloptd: job %lld: its state is recorded again\n", static_cast<long long>(job.id));
      return true;
    } catch (const storage::StorageError& e) {
      pause_claims();
      if (!retrying) {
        const std::string notice = "cannot record the job's state (" + std::string(e.what()) +
                                   "); retrying until the database accepts it - the job resumes by itself when "
                                   "there is room again";
        std::fprintf(stderr, "cycloptd: job %lld: %s\n", static_cast<long long>(job.id), notice.c_str());
        ctx.publish_notice(notice);
        retrying = true;
      }
    }
    std::unique_lock lock(mutex_);
    if (wake_.wait_for(lock, wait, [this] { return shutdown_.load(); })) {
      std::fprintf(stderr, "cycloptd: job %lld: shut down before its state could be recorded; the next start re-queues it\n",
                   static_cast<long long>(job.id));
      return false;
    }
    wait = std::min(2 * wait, std::chrono::duration_cast<std::chrono::steady_clock::duration>(kMaxRetry));
  }
}

void WorkerPool::run_job(const storage::JobRecord& job, std::shared_ptr<const service::ValidatedJobSpec> spec) {
  auto cancel = std::make_shared<std::atomic<bool>>(job.cancel_requested);
  {
    std::lock_guard lock(mutex_);
    cancel_flags_[job.id] = cancel;
    if (early_cancels_.erase(job.id)) *cancel = true;
  }
  std::string error;
  if (!spec) spec = parse_stored_spec(job, kinds_, error);
  WorkerJobContext ctx(job, spec ? service::effective_limits(spec->common.limits, config_.caps) : config_.caps,
                       config_.progress_hz, store_, publisher_, *cancel, shutdown_, executor_);
  if (spec) {
    try {
      executor_.run(job, *spec, ctx);
    } catch (const std::exception& e) {
      error = e.what();
    } catch (...) {
      error = "task '" + job.task + "' failed with a non-standard exception";
    }
  }
  ctx.flush_progress();
  const service::StopReason stop = ctx.stop_reason();
  {
    std::lock_guard lock(mutex_);
    cancel_flags_.erase(job.id);
  }
  if (!ctx.store_error().empty()) return requeue_after_store_failure(job, ctx);
  storage::JobState state = storage::JobState::done;
  std::optional<storage::JobOutcome> outcome;
  if (!error.empty()) {
    state = storage::JobState::failed;
  } else if (stop == service::StopReason::cancelled) {
    state = storage::JobState::cancelled;
  }
  // A job its limit stopped failed unless it had already stored and converged every point it
  // announced; either way its reason names the limit first, then what the stored points achieved.
  std::string limit_error;
  if (error.empty() && stop == service::StopReason::time_limit)
    limit_error = "limits.max_wall_seconds: exceeded " + std::to_string(ctx.limits().max_wall_seconds) + " s";
  if (error.empty() && stop == service::StopReason::iteration_limit)
    limit_error = "limits.max_iterations: exceeded " + std::to_string(ctx.limits().max_iterations);
  const double run_seconds = ctx.unrecorded_seconds();
  if (stop == service::StopReason::shutdown && error.empty()) {
    record_state(job, ctx, [&] {
      store_.return_to_queue(job.id, run_seconds, ctx.publish_seconds(), "server shutdown; resumes at next start");
    });
    return;
  }
  const bool recorded = record_state(job, ctx, [&] {
    if (state == storage::JobState::done) {  // ran to its end: judged by what it stored
      outcome = storage::judge_job_outcome(store_.required_points(job.id), store_.job(job.id)->points_total);
      state = outcome->state;
      error = outcome->summary;
      if (!limit_error.empty() && state != storage::JobState::done) {
        state = storage::JobState::failed;
        error = limit_error + "; " + error;
      }
    }
    store_.finish(job.id, state, error, run_seconds, ctx.publish_seconds(),
                  outcome ? std::optional<int>(outcome->converged) : std::nullopt);
  });
  if (!recorded) {
    publish_done(job, ctx, storage::JobState::queued,
                 "the server stopped before it could record the end of the job; it is re-queued at the next start");
    return;
  }
  publish_done(job, ctx, state, error, outcome);
}

void WorkerPool::requeue_after_store_failure(const storage::JobRecord& job, WorkerJobContext& ctx) {
  pause_claims();
  const std::string why = "could not store a point (" + ctx.store_error() + ")";
  std::fprintf(stderr, "cycloptd: job %lld: %s\n", static_cast<long long>(job.id), why.c_str());
  const double run_seconds = ctx.unrecorded_seconds();
  const bool requeued = record_state(job, ctx, [&] {
    store_.return_to_queue(job.id, run_seconds, ctx.publish_seconds(), "could not store: " + ctx.store_error());
  });
  publish_done(job, ctx, storage::JobState::queued,
               why + (requeued ? "; the job is re-queued and resumes from its stored points"
                               : "; the server stopped before it could re-queue the job; the next start does"));
}

void WorkerPool::pause_claims() {
  std::lock_guard lock(mutex_);
  claims_paused_until_ = std::chrono::steady_clock::now() + kStoreFailurePause;
}

void WorkerPool::publish_done(const storage::JobRecord& job, WorkerJobContext& ctx, storage::JobState state,
                              const std::string& error, const std::optional<storage::JobOutcome>& outcome) {
  ctx.finish_progress(state);
  cyclopt_lcm::job_done_t done;
  done.job_id = job.id;
  done.request_id = job.request_id;
  done.state = std::string(storage::to_string(state));
  done.points_stored = ctx.points_stored();
  done.run_seconds = job.run_seconds + ctx.elapsed_seconds();
  done.publish_seconds = ctx.publish_seconds();
  done.error = error;
  done.points_expected = outcome ? outcome->expected : -1;
  done.points_converged = outcome ? outcome->converged : -1;
  publisher_.publish(channels::kDone, done);
}

}  // namespace cyclopt::server
