#pragma once
// Where a claimed job runs. The worker pool hands every job to one executor with the job's
// JobContext (store, progress, limits, cancellation stay the pool's): the local executor runs the
// job kind on the worker thread itself (the default), the Slurm executor (remote/slurm_executor.hpp)
// runs it as a batch job through a shared spool and feeds the results back into the context.
// Each gets the job's spec parsed once (the worker pool's); the Slurm executor hands the stored
// text to cyclopt-worker, which parses it in its own process.
// Contract as JobKind::run: return normally when done or stopped, throw when the job failed.
// A job whose kind splits into work units (JobKind::run_unit) hands them back through its context
// (WorkerJobContext::run_units) to run_units: the local executor computes them on up to as many
// threads as the server has workers (the job's thread among them; a 16-foot comparison sweeps two
// feet at once on two cores), the Slurm executor submits each as a batch job and waits for all.

#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/unit_job_context.hpp"
#include "cyclopt/storage_read/job_record.hpp"

namespace cyclopt::server {

class JobExecutor {
 public:
  virtual ~JobExecutor() = default;
  virtual void run(const storage::JobRecord& job, const service::ValidatedJobSpec& spec,
                   service::JobContext& ctx) const = 0;
  virtual void run_units(const storage::JobRecord&, const std::vector<service::WorkUnit>& units,
                         const service::UnitRun& run, service::JobContext& ctx) const {
    service::run_units_here(units, run, ctx);
  }
};

class LocalExecutor final : public JobExecutor {
 public:
  explicit LocalExecutor(int unit_threads) : unit_threads_(unit_threads) {}
  void run(const storage::JobRecord&, const service::ValidatedJobSpec& spec, service::JobContext& ctx) const override {
    spec.run(ctx);
  }
  void run_units(const storage::JobRecord&, const std::vector<service::WorkUnit>& units, const service::UnitRun& run,
                 service::JobContext& ctx) const override {
    service::run_units_in_parallel(units, run, ctx, unit_threads_);
  }

 private:
  int unit_threads_;
};

}  // namespace cyclopt::server
