#pragma once
// What a job will cost, estimated from its spec before it is queued, and the server's limits on
// it: a job whose estimate exceeds a limit is rejected at submission, naming the spec field that
// drives the cost, the estimate and the limit - instead of running for hours or into bad_alloc.
// The estimates are expected values from calibrated per-iteration costs (walker_job_cost.hpp),
// not bounds: a job may still end at its time limit, which running jobs check within 1 s.

#include <string>

namespace cyclopt::service {

struct JobCost {
  double seconds = 0.0;       // expected wall time on this machine
  double memory_bytes = 0.0;  // expected peak memory of the job (all its threads)
  std::string field;          // the spec field that drives the cost, e.g. "multistart.starts"
  std::string breakdown;      // how the estimate was formed, e.g. "1000 solves x 700 iterations x ..."
};

struct CostLimits {
  double max_seconds = 3600.0;                   // the server's per-job wall-time cap
  double max_memory_bytes = 4096.0 * (1 << 20);  // per job
};

// Throws SpecError(cost.field, ...) with the estimate, its breakdown and the limit when the cost
// exceeds a limit.
void check_cost(const JobCost& cost, const CostLimits& limits);

// "41.7 h", "12 s", "3.2 GiB": for messages.
std::string duration_text(double seconds);
std::string memory_text(double bytes);

}  // namespace cyclopt::service
