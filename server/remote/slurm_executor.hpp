#pragma once
// Runs each job as one Slurm batch job of cyclopt-worker (a "unit": the spool directory
// SPOOL/cyclopt-<job id>-<hash of the request id>, named the same in Slurm).
//   - submit: unit.json + stored_keys.json (points the store holds are skipped), then sbatch;
//   - while it runs: ingest events (announce, curves, points) into the JobContext as they appear
//     (idempotent: the server stays the only database writer), forward progress, and on cancel or
//     a limit write the cancel file, give the worker a grace period, then scancel;
//   - a unit that leaves the queue without done.json (FAILED, CANCELLED by someone else, TIMEOUT,
//     PREEMPTED, NODE_FAIL, a killed worker) is submitted again, up to max_submissions, then the
//     job fails naming the unit and its last Slurm state;
//   - server shutdown or crash leaves units running: the next start finds them by name in
//     squeue and re-attaches instead of submitting them again.

#include "../job_executor.hpp"
#include "slurm_options.hpp"

namespace cyclopt::server::remote {

class SlurmExecutor final : public JobExecutor {
 public:
  explicit SlurmExecutor(SlurmOptions options);
  // Runs the job's stored spec text (service::runnable_spec_text) in cyclopt-worker, which parses it itself.
  void run(const storage::JobRecord& job, const service::ValidatedJobSpec& spec, service::JobContext& ctx) const override;

 private:
  SlurmOptions options_;
};

}  // namespace cyclopt::server::remote
