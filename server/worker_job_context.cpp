#include "worker_job_context.hpp"

#include "cyclopt_channels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
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
      meter_(job.points_stored),
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
  store_access([&] { store_.set_points_total(job_.id, points_total); });
}

void WorkerJobContext::add_curve(int curve_index, const std::string& name, const std::string& parameter_name) {
  store_access([&] { store_.add_curve(job_.id, curve_index, name, parameter_name); });
}

bool WorkerJobContext::store_point(const storage::SolutionPoint& point) {
  const bool added = store_access([&] {
    const bool new_point = store_.store_point(job_.id, point);
    checkpoint_time();
    return new_point;
  });
  if (added) ++points_stored_;
  return added;
}

void WorkerJobContext::checkpoint_time() {
  std::lock_guard lock(checkpoint_mutex_);
  last_checkpoint_ = std::chrono::steady_clock::now();
  const double now = elapsed_seconds();
  store_.add_run_seconds(job_.id, now - recorded_seconds_);
  recorded_seconds_ = now;
}

std::set<storage::PointKey> WorkerJobContext::already_stored_points() {
  return store_access([&] { return store_.stored_points(job_.id); });
}

void WorkerJobContext::store_checkpoint(const std::string& key, const std::string& value) {
  store_access([&] { store_.store_checkpoint(job_.id, key, value); });
}

std::map<std::string, std::string> WorkerJobContext::stored_checkpoints() {
  return store_access([&] { return store_.checkpoints(job_.id); });
}

service::StopReason WorkerJobContext::stop_reason() {
  republish_if_quiet();
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
  last_report_ = report;
  std::string& phase = phases_[report.unit];
  const bool phase_change = !report.phase.empty() && report.phase != phase;
  if (phase_change) phase = report.phase;
  const auto now = std::chrono::steady_clock::now();
  if (!phase_change && now - last_publish_ < min_interval_) {
    pending_ = report;
    return;
  }
  const cyclopt_lcm::job_progress_t m = publish(report);
  if (phase_change || now - last_record_ > kCheckpointInterval) record_progress(m, phase_change);
}

void WorkerJobContext::run_units(const std::vector<service::WorkUnit>& units, const service::UnitRun& run) {
  {
    std::lock_guard lock(progress_mutex_);
    meter_.units(static_cast<int>(units.size()));
  }
  executor_.run_units(job_, units, run, *this);
}

void WorkerJobContext::unit_ended(const std::string& unit_id) {
  std::lock_guard lock(progress_mutex_);
  meter_.unit_ended(unit_id, job_.run_seconds + elapsed_seconds());
  phases_.erase(unit_id);
}

void WorkerJobContext::republish_if_quiet() {
  std::unique_lock lock(progress_mutex_, std::try_to_lock);
  if (!lock || last_publish_ == std::chrono::steady_clock::time_point{}) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_publish_ < kQuietRepublish) return;
  const cyclopt_lcm::job_progress_t m = publish(pending_ ? *pending_ : last_report_);
  if (now - last_record_ > kCheckpointInterval) record_progress(m, false);
}

void WorkerJobContext::flush_progress() {
  std::lock_guard lock(progress_mutex_);
  if (!pending_) return;
  const service::ProgressReport last = *pending_;  // publish() resets pending_ before it reads the report
  publish(last);
}

void WorkerJobContext::publish_notice(const std::string& message) {
  std::lock_guard lock(progress_mutex_);
  service::ProgressReport r = last_report_;  // the job's progress as it stands, saying `message`
  r.message = message;
  publish(r);
}

void WorkerJobContext::finish_progress(storage::JobState state) {
  std::lock_guard lock(progress_mutex_);
  service::ProgressReport r = last_report_;
  r.phase = storage::to_string(state);
  r.iteration = -1;
  // A job judged done stored what it announced, although its kind's last report may have come
  // before its last point (an optimise job's came from the solve: "100% 0/1 | done").
  if (state == storage::JobState::done) r.points_done = std::max(r.points_done, r.points_total);
  cyclopt_lcm::job_progress_t m = message(r);
  const service::ProgressReading end = meter_.finish(state == storage::JobState::done || state == storage::JobState::incomplete);
  m.percent = end.percent;
  m.percent_is_lower_bound = end.lower_bound;
  m.eta_seconds = end.eta_seconds;
  publish_seconds_ += publisher_.publish(channels::kProgress, m);
  record_progress(m, false);
}

void WorkerJobContext::record_progress(const cyclopt_lcm::job_progress_t& m, bool phase_event) {
  last_record_ = std::chrono::steady_clock::now();
  const auto known = [](double v) { return std::isfinite(v) ? std::optional<double>(v) : std::nullopt; };
  const storage::JobProgressRecord p{m.percent, m.phase, known(m.eta_seconds), known(m.best_objective),
                                     m.timestamp_us * 1e-6};
  char text[64];
  std::snprintf(text, sizeof text, " | %s%.0f%% | ETA %s", m.percent_is_lower_bound ? ">=" : "", m.percent,
                service::clock_text(m.eta_seconds).c_str());
  std::string line = m.phase + text;
  if (std::isfinite(m.best_objective)) {
    std::snprintf(text, sizeof text, " | best %.6g", m.best_objective);
    line += text;
  }
  if (phase_event) std::fprintf(stderr, "cycloptd: job %lld: %s\n", static_cast<long long>(job_.id), line.c_str());
  try {
    store_.set_progress(job_.id, p);
    if (phase_event) store_.add_event(job_.id, "phase", line);
  } catch (const storage::StorageError&) {  // progress is not a result: a full disk loses only this record
  }
}

cyclopt_lcm::job_progress_t WorkerJobContext::message(const service::ProgressReport& r) const {
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
  m.message = r.message;
  m.phase = r.phase;
  m.phase_done = r.phase_done;
  m.phase_total = r.phase_total;
  m.best_objective = r.best_objective;
  m.elapsed_seconds = job_.run_seconds + elapsed_seconds();
  return m;
}

cyclopt_lcm::job_progress_t WorkerJobContext::publish(const service::ProgressReport& r) {
  pending_.reset();
  last_publish_ = std::chrono::steady_clock::now();
  cyclopt_lcm::job_progress_t m = message(r);
  service::ProgressReport resolved = r;
  resolved.points_total = m.points_total;
  const service::ProgressReading reading = meter_.read(resolved, m.elapsed_seconds, elapsed_seconds());
  m.percent = reading.percent;
  m.percent_is_lower_bound = reading.lower_bound;
  m.eta_seconds = reading.eta_seconds;
  publish_seconds_ += publisher_.publish(channels::kProgress, m);
  return m;
}

}  // namespace cyclopt::server
