#include "file_job_context.hpp"

namespace cyclopt::server::remote {

namespace {
// The cancel file is a stat() away; checking it at most this often keeps solver callbacks cheap.
constexpr auto kCancelCheckInterval = std::chrono::milliseconds(200);
}  // namespace

FileJobContext::FileJobContext(const UnitSpool& spool, const UnitSpec& spec, double progress_hz)
    : spool_(spool),
      spec_(spec),
      min_interval_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(1.0 / progress_hz))),
      stored_(spool.read_stored_keys()),
      checkpoints_(spool.read_checkpoints()),
      sequence_(spool.next_sequence()) {
  // Points and checkpoints an earlier run of this unit wrote but the server may not have ingested yet.
  for (const auto& [n, e] : spool.read_events(0))
    if (e.type == UnitEvent::Type::point)
      stored_.insert(e.point.key);
    else if (e.type == UnitEvent::Type::checkpoint)
      checkpoints_[e.checkpoint_key] = e.checkpoint_value;
}

void FileJobContext::append(const UnitEvent& event) {
  const std::lock_guard lock(mutex_);
  spool_.write_event(sequence_++, event);
}

void FileJobContext::store_checkpoint(const std::string& key, const std::string& value) {
  UnitEvent e;
  e.type = UnitEvent::Type::checkpoint;
  e.checkpoint_key = key;
  e.checkpoint_value = value;
  append(e);
  const std::lock_guard lock(mutex_);
  checkpoints_[key] = value;
}

std::map<std::string, std::string> FileJobContext::stored_checkpoints() {
  const std::lock_guard lock(mutex_);
  return checkpoints_;
}

void FileJobContext::announce(int points_total) {
  UnitEvent e;
  e.type = UnitEvent::Type::announce;
  e.points_total = points_total;
  append(e);
}

void FileJobContext::add_curve(int curve_index, const std::string& name, const std::string& parameter_name) {
  UnitEvent e;
  e.type = UnitEvent::Type::curve;
  e.curve_index = curve_index;
  e.curve_name = name;
  e.parameter_name = parameter_name;
  append(e);
}

bool FileJobContext::store_point(const storage::SolutionPoint& point) {
  if (!stored_.insert(point.key).second) return false;
  UnitEvent e;
  e.type = UnitEvent::Type::point;
  e.point = point;
  append(e);
  return true;
}

void FileJobContext::report_progress(const service::ProgressReport& report) {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_progress_ < min_interval_) return;
  last_progress_ = now;
  spool_.write_progress(report);
}

service::StopReason FileJobContext::stop_reason() {
  const auto now = std::chrono::steady_clock::now();
  if (!cancelled_ && now - last_cancel_check_ >= kCancelCheckInterval) {
    last_cancel_check_ = now;
    cancelled_ = spool_.cancel_requested();
  }
  if (cancelled_) return service::StopReason::cancelled;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed + spec_.run_seconds_before > spec_.limits.max_wall_seconds) return service::StopReason::time_limit;
  if (iterations_ >= spec_.limits.max_iterations) return service::StopReason::iteration_limit;
  return service::StopReason::none;
}

}  // namespace cyclopt::server::remote
