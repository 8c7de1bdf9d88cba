#pragma once
// A job context in memory for tests of what a job or its units did to their job: the curves, the
// keys of the stored points, the progress reports and checkpoints; stop is the job's stop reason.
#include "cyclopt/service/job_context.hpp"

#include <atomic>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace cyclopt::service {

class MemoryJob final : public JobContext {
 public:
  std::int64_t job_id() const override { return 7; }
  const JobLimits& limits() const override { return limits_; }
  void report_progress(const ProgressReport& r) override {
    const std::lock_guard<std::mutex> lock(mutex);
    reports.push_back(r);
  }
  void count_iterations(int) override {}
  void announce(int) override {}
  void add_curve(int curve, const std::string&, const std::string&) override {
    const std::lock_guard<std::mutex> lock(mutex);
    curves.push_back(curve);
  }
  bool store_point(const storage::SolutionPoint& p) override {
    const std::lock_guard<std::mutex> lock(mutex);  // a job context takes calls from all its units at once
    return points.insert(p.key).second;
  }
  std::set<storage::PointKey> already_stored_points() override {
    const std::lock_guard<std::mutex> lock(mutex);
    return points;
  }
  void store_checkpoint(const std::string& key, const std::string& value) override {
    const std::lock_guard<std::mutex> lock(mutex);  // units in parallel store at once
    checkpoints[key] = value;
  }
  std::map<std::string, std::string> stored_checkpoints() override {
    const std::lock_guard<std::mutex> lock(mutex);
    return checkpoints;
  }
  StopReason stop_reason() override { return stop; }

  JobLimits limits_;
  std::vector<int> curves;
  std::set<storage::PointKey> points;
  std::vector<ProgressReport> reports;
  std::map<std::string, std::string> checkpoints;
  std::atomic<StopReason> stop{StopReason::none};
  std::mutex mutex;
};

}  // namespace cyclopt::service
