#pragma once
// Runs each job as one Slurm batch job of cyclopt-worker (a "unit": the spool directory
// SPOOL/cyclopt-<job id>-<hash of the request id>, named the same in Slurm); a job whose kind
// splits into work units (JobKind::run_unit: the feet of a comparison) runs on the server thread
// and each of its units is such a batch job (SPOOL/cyclopt-<job id>-<hash>-<unit id>).
//   - submit: unit.json + stored_keys.json (points the store holds are skipped), then sbatch;
//   - while it runs: ingest events (announce, curves, points) into the JobContext as they appear
//     (idempotent: the server stays the only database writer), forward progress, and on cancel or
//     a limit write the cancel file, give the worker a grace period, then scancel;
//   - a unit that leaves the queue without done.json (FAILED, CANCELLED by someone else, TIMEOUT,
//     PREEMPTED, NODE_FAIL, a killed worker) is submitted again, up to max_submissions, then the
//     job fails naming the unit and its last Slurm state;
//   - server shutdown or crash leaves units running: the next start finds them by name in
//     squeue and re-attaches instead of submitting them again;
//   - while squeue cannot reach the controller (restart, outage) nothing is known to have ended:
//     units are not resubmitted, results their workers write still count, a stop still asks
//     the worker and scancels; a start that cannot ask squeue fails instead of submitting twice.

#include "../job_executor.hpp"
#include "slurm_options.hpp"

namespace cyclopt::server::remote {

class SlurmExecutor final : public JobExecutor {
 public:
  explicit SlurmExecutor(SlurmOptions options);
  // Runs the job's stored spec text (service::runnable_spec_text) in cyclopt-worker, which parses it itself.
  // A kind with work units runs here instead, and its units come to run_units.
  void run(const storage::JobRecord& job, const service::ValidatedJobSpec& spec, service::JobContext& ctx) const override;
  // Every unit as its own Slurm job (SPOOL/cyclopt-<job id>-<hash>-<unit id>), all submitted at
  // once; returns when all have ended. A unit that fails for good stops the others and fails the job.
  void run_units(const storage::JobRecord& job, const std::vector<service::WorkUnit>& units,
                 const service::UnitRun& run, service::JobContext& ctx) const override;

 private:
  SlurmOptions options_;
};

}  // namespace cyclopt::server::remote
