#include "cyclopt/service/unit_job_context.hpp"

#include <stdexcept>

namespace cyclopt::service {

std::string unit_checkpoint_prefix(const std::string& unit_id) { return "unit/" + unit_id + "/"; }

UnitJobContext::UnitJobContext(JobContext& job, const WorkUnit& unit) : job_(job), prefix_(unit_checkpoint_prefix(unit.id)) {}

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

void run_units_here(const std::vector<WorkUnit>& units, const UnitRun& run, JobContext& job) {
  for (const WorkUnit& unit : units) {
    if (job.stop_reason() != StopReason::none) return;
    UnitJobContext ctx(job, unit);
    try {
      run(unit, ctx);
    } catch (const std::exception& e) {
      throw std::runtime_error("work unit " + unit.id + ": " + e.what());
    }
  }
}

void JobContext::run_units(const std::vector<WorkUnit>& units, const UnitRun& run) { run_units_here(units, run, *this); }

}  // namespace cyclopt::service
