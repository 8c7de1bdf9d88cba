#pragma once
// The JobContext a worker hands to a job kind: commits points to the store, publishes progress
// at most progress_hz times per second (a phase change at once: it is also stored as an event,
// logged, and the job's progress recorded in the store, as every few seconds), and answers stop_reason() from the cancel flag, the
// server's shutdown flag and the job's time and iteration limits (time summed over attempts and
// checkpointed to the store every few seconds, so a kill -9 loses at most that much).
// report_progress, count_iterations and stop_reason may be called from several threads at once
// (a multistart's solves), and so may store_point, already_stored_points, store_checkpoint and
// stored_checkpoints (work units run in parallel by the local executor); announce and add_curve
// from the job's worker thread.

#include "cyclopt/service/job_context.hpp"
#include "cyclopt/service/progress_meter.hpp"
#include "cyclopt/storage_read/job_record.hpp"
#include "cyclopt/storage/result_store.hpp"
#include "job_executor.hpp"
#include "lcm_publisher.hpp"

#include <cyclopt_lcm/job_progress_t.hpp>

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace cyclopt::server {

class WorkerJobContext final : public service::JobContext {
 public:
  WorkerJobContext(const storage::JobRecord& job, const service::JobLimits& limits, double progress_hz,
                   storage::ResultStore& store, LcmPublisher& publisher, const std::atomic<bool>& cancel,
                   const std::atomic<bool>& shutdown, const JobExecutor& executor);

  std::int64_t job_id() const override { return job_.id; }
  const service::JobLimits& limits() const override { return limits_; }
  void report_progress(const service::ProgressReport& report) override;
  void count_iterations(int n) override { iterations_ += n; }
  void announce(int points_total) override;
  void add_curve(int curve_index, const std::string& name, const std::string& parameter_name) override;
  bool store_point(const storage::SolutionPoint& point) override;
  std::set<storage::PointKey> already_stored_points() override;
  void store_checkpoint(const std::string& key, const std::string& value) override;
  std::map<std::string, std::string> stored_checkpoints() override;
  service::StopReason stop_reason() override;
  // The executor's (job_executor.hpp): here, or on Slurm.
  void run_units(const std::vector<service::WorkUnit>& units, const service::UnitRun& run) override;
  void unit_ended(const std::string& unit_id) override;

  // Publishes the last report if rate limiting held it back.
  void flush_progress();
  // The job ended in `state`: publishes and stores its last progress (100 % if it ran to its
  // end) with the state as phase.
  void finish_progress(storage::JobState state);
  // Publishes a progress message that says only `message` (what the worker does about a fault).
  void publish_notice(const std::string& message);
  double elapsed_seconds() const;
  // This attempt's seconds not yet added to the store's run_seconds.
  double unrecorded_seconds() {
    std::lock_guard lock(checkpoint_mutex_);
    return elapsed_seconds() - recorded_seconds_;
  }
  // Why the last store access of the job failed ("" if none did): the job is then re-queued, not
  // failed - a full disk is the server's trouble, not the job's.
  std::string store_error() {
    std::lock_guard lock(store_error_mutex_);
    return store_error_;
  }
  double publish_seconds() const { return publish_seconds_; }
  int points_stored() const { return points_stored_; }

 private:
  // The message of a report, without percentage and ETA (the meter's).
  cyclopt_lcm::job_progress_t message(const service::ProgressReport& report) const;
  // Publishes the report (callers hold progress_mutex_) and returns the message sent.
  cyclopt_lcm::job_progress_t publish(const service::ProgressReport& report);
  // The message's progress into the jobs table; `phase_event`: also an event and a log line.
  void record_progress(const cyclopt_lcm::job_progress_t& m, bool phase_event);
  // Runs a store access of the job's (its points, curves, checkpoints, announced total): a
  // StorageError is recorded as store_error() before it propagates through the job.
  template <class Access>
  auto store_access(Access&& access) -> decltype(access()) {
    try {
      return access();
    } catch (const storage::StorageError& e) {
      std::lock_guard lock(store_error_mutex_);
      store_error_ = e.what();
      throw;
    }
  }
  void checkpoint_time();
  std::chrono::steady_clock::time_point last_checkpoint();
  static constexpr std::chrono::seconds kCheckpointInterval{5};
  // A long solve reports nothing for a while: stop_reason(), which solvers poll, publishes the last
  // report again after this long, so the run time and ETA move (try-lock: never waits for it).
  void republish_if_quiet();
  static constexpr std::chrono::seconds kQuietRepublish{1};

  const storage::JobRecord& job_;
  service::JobLimits limits_;
  std::chrono::steady_clock::duration min_interval_;
  storage::ResultStore& store_;
  LcmPublisher& publisher_;
  const std::atomic<bool>& cancel_;
  const std::atomic<bool>& shutdown_;
  const JobExecutor& executor_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_publish_{};
  std::mutex progress_mutex_;  // last_publish_, pending_
  std::optional<service::ProgressReport> pending_;
  service::ProgressReport last_report_;  // the last one published or pending
  service::ProgressMeter meter_;
  std::map<std::string, std::string> phases_;  // per unit ("": the job), of its last report: a different one is a phase change
  std::chrono::steady_clock::time_point last_record_{};  // progress into the store
  std::atomic<long long> iterations_{0};
  std::mutex checkpoint_mutex_;  // last_checkpoint_, recorded_seconds_
  std::chrono::steady_clock::time_point last_checkpoint_ = start_;
  double recorded_seconds_ = 0.0;  // of this attempt, in the store
  std::mutex store_error_mutex_;
  std::string store_error_;
  int points_total_ = -1;
  std::atomic<int> points_stored_{0};
  int points_at_start_ = 0;  // stored by earlier attempts
  double publish_seconds_ = 0.0;
};

}  // namespace cyclopt::server
