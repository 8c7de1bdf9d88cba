#include "worker_job_context.hpp"

#include <cyclopt_lcm/job_progress_t.hpp>

#include "cyclopt_channels.hpp"

#include <cmath>
#include <limits>

namespace cyclopt::server {

WorkerJobContext::WorkerJobContext(const storage::JobRecord& job, const service::JobLimits& limits, double progress_hz,
                                   storage::ResultStore& store, LcmPublisher& publisher,
                                   const std::atomic<bool>& cancel, const std::atomic<bool>& shutdown,
                                   const JobExecutor& executor)
    : job_(job),
      limits_(limits),
      min_interval_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(1.0 / progress_hz))),
      store_(store),
      publisher_(publisher),
      cancel_(cancel),
      shutdown_(shutdown),
      executor_(executor),
      points_stored_(job.points_stored),
      points_at_start_(job.points_stored) {}

std::chrono::steady_clock::time_point WorkerJobContext::last_checkpoint() {
  std::lock_guard lock(checkpoint_mutex_);
  return last_checkpoint_;
}

double WorkerJobContext::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void WorkerJobContext::announce(int points_total) {
  points_total_ = points_total;
  store_.set_points_total(job_.id, points_total);
}

void WorkerJobContext::add_curve(int curve_index, const std::string& name, const std::string& parameter_name) {
  store_.add_curve(job_.id, curve_index, name, parameter_name);
}

bool WorkerJobContext::store_point(const storage::SolutionPoint& point) {
  bool added = false;
  try {
    added = store_.store_point(job_.id, point);
    checkpoint_time();
  } catch (const storage::StorageError& e) {
    record_store_error(e);
    throw;
  }
  if (added) ++points_stored_;
  return added;
}

void WorkerJobContext::record_store_error(const storage::StorageError& e) {
  std::lock_guard lock(store_error_mutex_);
  store_error_ = e.what();
}

void WorkerJobContext::checkpoint_time() {
  std::lock_guard lock(checkpoint_mutex_);
  last_checkpoint_ = std::chrono::steady_clock::now();
  const double now = elapsed_seconds();
  store_.add_run_seconds(job_.id, now - recorded_seconds_);
  recorded_seconds_ = now;
}

std::set<storage::PointKey> WorkerJobContext::already_stored_points() { return store_.stored_points(job_.id); }

void WorkerJobContext::store_checkpoint(const std::string& key, const std::string& value) {
  try {
    store_.store_checkpoint(job_.id, key, value);
  } catch (const storage::StorageError& e) {  // as for a point: the job is re-queued
    record_store_error(e);
    throw;
  }
}

service::StopReason WorkerJobContext::stop_reason() {
  if (std::chrono::steady_clock::now() - last_checkpoint() > kCheckpointInterval) try {
      checkpoint_time();
    } catch (const storage::StorageError&) {  // a full disk: the time is recorded when the attempt ends
    }
  if (cancel_.load()) return service::StopReason::cancelled;
  if (shutdown_.load()) return service::StopReason::shutdown;
  if (elapsed_seconds() + job_.run_seconds > limits_.max_wall_seconds) return service::StopReason::time_limit;
  if (iterations_ >= limits_.max_iterations) return service::StopReason::iteration_limit;
  return service::StopReason::none;
}

void WorkerJobContext::report_progress(const service::ProgressReport& report) {
  std::lock_guard lock(progress_mutex_);
  const auto now = std::chrono::steady_clock::now();
  if (now - last_publish_ < min_interval_) {
    pending_ = report;
    return;
  }
  publish(report);
}

void WorkerJobContext::flush_progress() {
  std::lock_guard lock(progress_mutex_);
  if (!pending_) return;
  const service::ProgressReport last = *pending_;  // publish() resets pending_ before it reads the report
  publish(last);
}

void WorkerJobContext::publish_notice(const std::string& message) {
  std::lock_guard lock(progress_mutex_);
  service::ProgressReport r;
  r.points_done = points_stored_;
  r.message = message;
  publish(r);
}

void WorkerJobContext::publish(const service::ProgressReport& r) {
  const auto now = std::chrono::steady_clock::now();
  pending_.reset();
  last_publish_ = now;
  cyclopt_lcm::job_progress_t m;
  m.job_id = job_.id;
  m.request_id = job_.request_id;
  m.task = job_.task;
  m.timestamp_us = std::chrono::duration_cast<std::chrono::microseconds>(
                       std::chrono::system_clock::now().time_since_epoch()).count();
  m.iteration = r.iteration;
  m.objective = r.objective;
  m.constraint_violation = r.constraint_violation;
  m.parameter = r.parameter;
  m.curve_id = r.curve_id;
  m.points_done = r.points_done;
  m.points_total = r.points_total >= 0 ? r.points_total : points_total_;
  m.percent = m.points_total > 0 ? 100.0 * m.points_done / m.points_total : std::numeric_limits<double>::quiet_NaN();
  const int solved_now = m.points_done - points_at_start_;
  m.eta_seconds = std::isfinite(r.eta_seconds) ? r.eta_seconds
                 : solved_now > 0 && m.points_total > 0
                      ? elapsed_seconds() / solved_now * (m.points_total - m.points_done)
                      : std::numeric_limits<double>::quiet_NaN();
  m.message = r.message;
  m.phase = r.phase;
  m.phase_done = r.phase_done;
  m.phase_total = r.phase_total;
  m.best_objective = r.best_objective;
  m.elapsed_seconds = job_.run_seconds + elapsed_seconds();
  publish_seconds_ += publisher_.publish(channels::kProgress, m);
}

}  // namespace cyclopt::server
