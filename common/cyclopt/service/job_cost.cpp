#include "cyclopt/service/job_cost.hpp"

#include "cyclopt/service/spec_fields.hpp"

#include <cstdio>

namespace cyclopt::service {

std::string duration_text(double seconds) {
  char buf[64];
  if (seconds < 120.0)
    std::snprintf(buf, sizeof buf, "%.3g s", seconds);
  else if (seconds < 7200.0)
    std::snprintf(buf, sizeof buf, "%.3g min", seconds / 60.0);
  else
    std::snprintf(buf, sizeof buf, "%.3g h", seconds / 3600.0);
  return buf;
}

std::string memory_text(double bytes) {
  char buf[64];
  if (bytes < 1024.0 * 1024.0 * 1024.0)
    std::snprintf(buf, sizeof buf, "%.3g MiB", bytes / (1024.0 * 1024.0));
  else
    std::snprintf(buf, sizeof buf, "%.3g GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  return buf;
}

void check_cost(const JobCost& cost, const CostLimits& limits) {
  const std::string field = cost.field.empty() ? "spec_json" : cost.field;
  if (cost.memory_bytes > limits.max_memory_bytes)
    throw SpecError(field, "the job needs an estimated " + memory_text(cost.memory_bytes) + " of memory (" +
                               cost.breakdown + "), more than the server's limit of " +
                               memory_text(limits.max_memory_bytes) + " per job (cycloptd --max-job-memory-mb)");
  if (cost.seconds > limits.max_seconds)
    throw SpecError(field, "the job is estimated to run " + duration_text(cost.seconds) + " (" +
                               cost.breakdown + "), more than the server's limit of " +
                               duration_text(limits.max_seconds) + " per job (cycloptd --max-job-seconds)");
}

}  // namespace cyclopt::service
