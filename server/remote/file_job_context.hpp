#pragma once
// The JobContext of a cyclopt-worker: the job kind runs exactly as on a server worker thread, but
// points, curves and progress go into the unit's spool (unit_spool.hpp) for cycloptd to ingest,
// and stop_reason() answers from the spool's cancel file and the unit's own limits.

#include "unit_spool.hpp"

#include <chrono>
#include <map>
#include <mutex>
#include <set>

namespace cyclopt::server::remote {

class FileJobContext final : public service::JobContext {
 public:
  FileJobContext(const UnitSpool& spool, const UnitSpec& spec, double progress_hz);

  std::int64_t job_id() const override { return spec_.job_id; }
  const service::JobLimits& limits() const override { return spec_.limits; }
  void report_progress(const service::ProgressReport& report) override;
  void count_iterations(int n) override { iterations_ += n; }
  void announce(int points_total) override;
  void add_curve(int curve_index, const std::string& name, const std::string& parameter_name) override;
  bool store_point(const storage::SolutionPoint& point) override;
  std::set<storage::PointKey> already_stored_points() override { return stored_; }
  void store_checkpoint(const std::string& key, const std::string& value) override;
  std::map<std::string, std::string> stored_checkpoints() override;
  service::StopReason stop_reason() override;

 private:
  void append(const UnitEvent& event);

  const UnitSpool& spool_;
  UnitSpec spec_;
  std::chrono::steady_clock::duration min_interval_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_progress_{};
  std::chrono::steady_clock::time_point last_cancel_check_{};
  bool cancelled_ = false;
  std::set<storage::PointKey> stored_;  // by the server, or by earlier runs of this unit
  std::map<std::string, std::string> checkpoints_;  // likewise
  std::mutex mutex_;  // append() and checkpoints_: checkpoints come from multistart threads
  int sequence_ = 0;
  long long iterations_ = 0;
};

}  // namespace cyclopt::server::remote
