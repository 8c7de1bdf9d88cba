#pragma once
// The interface a running job sees (implemented by the server's worker; tests implement it in
// memory). All methods are called from the job's own worker thread, except where an executor runs
// a job's work units on several threads (run_units_in_parallel, unit_job_context.hpp): that
// executor's context takes calls from all of them at once.

#include "cyclopt/service/progress_report.hpp"
#include "cyclopt/storage_read/solution_point.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace cyclopt::service {

enum class StopReason { none, cancelled, time_limit, iteration_limit, shutdown };
const char* to_string(StopReason r);

// Per-job limits after the server's caps were applied to the spec's "limits".
struct JobLimits {
  double max_wall_seconds = 3600.0;
  // Summed over all points (solver iterations or point evaluations). A backstop against runaway
  // loops: the time limit is the guard that prices a job (a 21-speed rolling-foot sweep needs over
  // 1e5 SQP iterations).
  int max_iterations = 10000000;
};

class JobContext;

// An independent part of a job (issue 18): the foot of a comparison, say. A job kind that splits
// its work this way gives JobKind::run_unit, which computes part `index` of the kind's spec; the
// job's run() hands the parts to JobContext::run_units, and the server's executor decides where
// they run (here, or each as its own Slurm batch job of cyclopt-worker).
struct WorkUnit {
  std::string id;  // unique in its job and the same in every attempt, [a-z0-9-] (e.g. "foot-3")
  int index = 0;   // the part of the spec it computes
};
// Computes one unit through the context it is given (a unit_job_context.hpp view of the job).
using UnitRun = std::function<void(const WorkUnit& unit, JobContext& ctx)>;

class JobContext {
 public:
  virtual ~JobContext() = default;

  virtual std::int64_t job_id() const = 0;
  virtual const JobLimits& limits() const = 0;

  // Rate-limited: cheap to call after every solver iteration.
  virtual void report_progress(const ProgressReport& report) = 0;
  // Counts towards limits().max_iterations; call once per solver iteration or point evaluation.
  virtual void count_iterations(int n) = 0;

  // Declare the curves and the number of points before solving, so progress has a percentage.
  virtual void announce(int points_total) = 0;
  virtual void add_curve(int curve_index, const std::string& name, const std::string& parameter_name) = 0;

  // Commits the point durably before returning (false if it was already stored).
  virtual bool store_point(const storage::SolutionPoint& point) = 0;
  // Points committed by earlier attempts of this job: a resumed job skips them.
  virtual std::set<storage::PointKey> already_stored_points() = 0;
  // Intermediate results a resumed job reuses instead of computing them again (a sweep's finished
  // solves and continuation runs: studies/sweep_journal.hpp); durable before returning, never
  // shown as results. store_checkpoint may be called from several threads (one at a time).
  virtual void store_checkpoint(const std::string& key, const std::string& value) = 0;
  virtual std::map<std::string, std::string> stored_checkpoints() = 0;

  // Poll between points and inside solver callbacks; return as soon as it is not `none`.
  virtual StopReason stop_reason() = 0;

  // Runs the job's units and returns when every one has ended, or early once stop_reason() is not
  // `none`; throws (std::runtime_error naming the unit) when one failed. Each unit sees the job
  // through a UnitJobContext (unit_job_context.hpp): the job's curves and points, its own
  // checkpoints. Default: here, one after another (run_units_here); the server's context asks its
  // executor. `run` must compute what JobKind::run_unit computes: a remote worker calls that.
  virtual void run_units(const std::vector<WorkUnit>& units, const UnitRun& run);
  // The unit returned (done, stopped or failed): its progress no longer counts (run_units_here and
  // run_units_in_parallel call it; the server's context forgets the unit's ETA).
  virtual void unit_ended(const std::string& unit_id) { (void)unit_id; }
};

}  // namespace cyclopt::service
