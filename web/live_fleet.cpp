#include "live_fleet.hpp"

#include <algorithm>

namespace cyclopt::web {

namespace {

void apply_live(FleetRow& row, const cyclopt_lcm::job_progress_t& p) {
  client::apply_progress(row.job, p);
  row.progress_us = p.timestamp_us;
}

}  // namespace

void LiveFleet::refresh(const nlohmann::json& job_rows) {
  std::vector<FleetRow> rows;
  for (const nlohmann::json& r : job_rows) rows.push_back(fleet_row(r));
  number_queue(rows);
  std::lock_guard lock(mutex_);
  bool any = false;
  for (FleetRow& row : rows) {
    Entry& e = jobs_[row.job.id];
    if (row.job.state == "running" && e.progress) apply_live(row, *e.progress);
    if (!e.row || to_json(*e.row) != to_json(row)) {
      e.row = std::move(row);
      e.row_seq = ++seq_;
      any = true;
    }
  }
  if (any) changed_.notify_all();
}

void LiveFleet::apply(const cyclopt_lcm::job_progress_t& p) {
  std::lock_guard lock(mutex_);
  Entry& e = jobs_[p.job_id];
  e.progress = p;
  e.progress_seq = ++seq_;
  if (p.percent >= 100.0) refresh_due_ = true;
  if (e.row && (e.row->job.state == "running" || e.row->job.state == "queued")) {
    apply_live(*e.row, p);
    e.row_seq = seq_;
  }
  changed_.notify_all();
}

LiveFleet::Changes LiveFleet::rows_since(std::uint64_t seq) const {
  std::lock_guard lock(mutex_);
  Changes c;
  c.seq = seq_;
  for (const auto& [id, e] : jobs_)
    if (e.row && e.row_seq > seq) c.rows.push_back(*e.row);
  return c;
}

LiveFleet::JobView LiveFleet::job(std::int64_t id) const {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return {};
  return {it->second.row, it->second.progress, std::max(it->second.row_seq, it->second.progress_seq)};
}

std::uint64_t LiveFleet::wait(std::uint64_t seq, std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, timeout, [&] { return stopped_ || seq_ > seq; });
  return seq_;
}

void LiveFleet::wait_for_refresh(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, timeout, [&] { return stopped_ || refresh_due_; });
  refresh_due_ = false;
}

void LiveFleet::stop() {
  std::lock_guard lock(mutex_);
  stopped_ = true;
  changed_.notify_all();
}

bool LiveFleet::stopped() const {
  std::lock_guard lock(mutex_);
  return stopped_;
}

}  // namespace cyclopt::web
