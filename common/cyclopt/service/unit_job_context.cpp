#include "cyclopt/service/unit_job_context.hpp"

#include <algorithm>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace cyclopt::service {

std::string unit_checkpoint_prefix(const std::string& unit_id) { return "unit/" + unit_id + "/"; }

UnitJobContext::UnitJobContext(JobContext& job, const WorkUnit& unit, const std::atomic<bool>* abandoned)
    : job_(job), unit_id_(unit.id), prefix_(unit_checkpoint_prefix(unit.id)), abandoned_(abandoned) {}

void UnitJobContext::report_progress(const ProgressReport& report) {
  if (!report.unit.empty()) return job_.report_progress(report);
  ProgressReport named = report;
  named.unit = unit_id_;
  job_.report_progress(named);
}

StopReason UnitJobContext::stop_reason() {
  if (abandoned_ && abandoned_->load()) return StopReason::cancelled;
  return job_.stop_reason();
}

void UnitJobContext::announce(int) {
  throw std::logic_error("work unit '" + prefix_ + "' announced points: its job announces the points of all its units");
}

void UnitJobContext::store_checkpoint(const std::string& key, const std::string& value) {
  job_.store_checkpoint(prefix_ + key, value);
}

std::map<std::string, std::string> UnitJobContext::stored_checkpoints() {
  std::map<std::string, std::string> own;
  for (auto& [key, value] : job_.stored_checkpoints())
    if (key.compare(0, prefix_.size(), prefix_) == 0) own.emplace(key.substr(prefix_.size()), std::move(value));
  return own;
}

void UnitJobContext::run_units(const std::vector<WorkUnit>&, const UnitRun&) {
  throw std::logic_error("work unit '" + prefix_ + "' split into units: units do not split again");
}

namespace {

// Units on `threads` threads (this one among them; 1: none started), each taking the next unit that
// has not started, until all ran, the job stops or a unit throws; then throws the first failure.
void run_units_on(const std::vector<WorkUnit>& units, const UnitRun& run, JobContext& job, std::size_t threads) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex error_mutex;
  std::string error;  // of the first unit that threw
  const auto work = [&] {
    for (std::size_t i = next++; i < units.size() && !failed.load() && job.stop_reason() == StopReason::none; i = next++) {
      UnitJobContext ctx(job, units[i], &failed);
      std::string what;
      try {
        run(units[i], ctx);
        job.unit_ended(units[i].id);
        continue;
      } catch (const std::exception& e) {
        what = e.what();
      } catch (...) {
        what = "unknown exception";
      }
      job.unit_ended(units[i].id);
      const std::lock_guard<std::mutex> lock(error_mutex);
      if (!failed.exchange(true)) error = "work unit " + units[i].id + ": " + what;
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (failed.load()) throw std::runtime_error(error);
}

}  // namespace

void run_units_here(const std::vector<WorkUnit>& units, const UnitRun& run, JobContext& job) {
  run_units_on(units, run, job, 1);
}

void run_units_in_parallel(const std::vector<WorkUnit>& units, const UnitRun& run, JobContext& job, int threads) {
  run_units_on(units, run, job, std::min(units.size(), static_cast<std::size_t>(std::max(threads, 1))));
}

void JobContext::run_units(const std::vector<WorkUnit>& units, const UnitRun& run) { run_units_here(units, run, *this); }

}  // namespace cyclopt::service
