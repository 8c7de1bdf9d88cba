#pragma once
// How a work unit (job_context.hpp) sees its job: the job's limits, progress, curves, points and
// stop reason unchanged, but checkpoints of its own, kept in the job's under "unit/<id>/" (so the
// sweep journals of two feet never mix, and a unit's result checkpoint names its unit). The same
// view wraps a unit computed here and a unit whose events cycloptd ingests from a cyclopt-worker,
// so both store the same keys.

#include "cyclopt/service/job_context.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <stdexcept>

namespace cyclopt::service {

// "unit/<id>/": the prefix of a unit's checkpoints in its job's.
std::string unit_checkpoint_prefix(const std::string& unit_id);

class UnitJobContext final : public JobContext {
 public:
  // `abandoned` (optional): set when a sibling unit running at the same time failed; this unit then
  // sees StopReason::cancelled and ends as a stopped unit would (its journal kept for the retry).
  UnitJobContext(JobContext& job, const WorkUnit& unit, const std::atomic<bool>* abandoned = nullptr);

  std::int64_t job_id() const override { return job_.job_id(); }
  const JobLimits& limits() const override { return job_.limits(); }
  // The report, naming this unit (ProgressReport::unit).
  void report_progress(const ProgressReport& report) override;
  void count_iterations(int n) override { job_.count_iterations(n); }
  // The job announced the points of all its units: a unit announcing throws std::logic_error.
  void announce(int points_total) override;
  void add_curve(int curve_index, const std::string& name, const std::string& parameter_name) override {
    job_.add_curve(curve_index, name, parameter_name);
  }
  bool store_point(const storage::SolutionPoint& point) override { return job_.store_point(point); }
  std::set<storage::PointKey> already_stored_points() override { return job_.already_stored_points(); }
  void store_checkpoint(const std::string& key, const std::string& value) override;
  std::map<std::string, std::string> stored_checkpoints() override;  // this unit's, without the prefix
  StopReason stop_reason() override;
  void unit_ended(const std::string& unit_id) override { job_.unit_ended(unit_id); }
  // Units do not split again: throws std::logic_error.
  void run_units(const std::vector<WorkUnit>& units, const UnitRun& run) override;

 private:
  JobContext& job_;
  std::string unit_id_;
  std::string prefix_;
  const std::atomic<bool>* abandoned_;
};

// The checkpoint `key` that `unit` left as its result (among the job's `stored` checkpoints), parsed
// by parse(json); std::runtime_error naming the unit when it is missing or parse throws.
template <class Parse>
auto unit_result(const std::map<std::string, std::string>& stored, const WorkUnit& unit, const std::string& key,
                 Parse parse) -> decltype(parse(nlohmann::json())) {
  const auto it = stored.find(unit_checkpoint_prefix(unit.id) + key);
  if (it == stored.end()) throw std::runtime_error("work unit " + unit.id + " ended without its result '" + key + "'");
  try {
    return parse(nlohmann::json::parse(it->second));
  } catch (const std::exception& e) {
    throw std::runtime_error("work unit " + unit.id + ": unreadable result '" + key + "' (" + e.what() + ")");
  }
}

// JobContext::run_units' default: each unit in turn on this thread, until the job stops.
void run_units_here(const std::vector<WorkUnit>& units, const UnitRun& run, JobContext& job);

// The same on up to `threads` threads at once (this one among them), each taking the next unit
// that has not started: units are independent by contract (the Slurm executor runs them all at
// once too), so only the job's context is shared, and it must take calls from `threads` threads
// at once. The first unit that throws fails the job (std::runtime_error naming the unit) once
// the units running beside it have stopped; no unit starts after it. threads <= 1: run_units_here.
void run_units_in_parallel(const std::vector<WorkUnit>& units, const UnitRun& run, JobContext& job, int threads);

}  // namespace cyclopt::service
