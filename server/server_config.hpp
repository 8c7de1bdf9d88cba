#pragma once
// cycloptd's settings: defaults, then a JSON config file (--config), then command-line flags.
//
//   {"database": "cyclopt.db", "lcm_url": "udpm://239.255.76.67:7667?ttl=0", "workers": 2,
//    "max_job_seconds": 3600, "max_job_iterations": 10000000, "max_job_memory_mb": 4096,
//    "max_queued_jobs": 100, "max_queued_hours": 168, "progress_hz": 5,
//    "executor": "slurm", "slurm": {"spool": "/shared/cyclopt-spool", "partition": "batch", "account": "lab",
//                                   "cpus_per_unit": 2, "time_limit_minutes": 120, "max_submissions": 4,
//                                   "poll_seconds": 0.5, "worker": "/usr/local/bin/cyclopt-worker"},
//    "auth_secret_file": "/etc/cyclopt/keys", "auth_reads": "owner"}
// auth_secret_file (message_auth.hpp) and auth_reads are accepted in the config file only.

#include "cyclopt/service/job_context.hpp"
#include "cyclopt/storage/result_store.hpp"
#include "remote/slurm_options.hpp"

#include <string>
#include <vector>

namespace cyclopt::server {

// Under authentication, who may read a job (status, list, query, watch): its submitter's key and
// admin keys (owner), or every key of the key file (any). Cancel is always the owner's.
enum class AuthReads { owner, any };

struct ServerConfig {
  std::string database = "cyclopt.db";
  std::string lcm_url;  // empty: LCM's default (LCM_DEFAULT_URL or udpm multicast)
  int workers = 0;      // 0: one per core
  service::JobLimits caps;  // per-job time and iteration limits (specs may only lower them)
  double max_job_memory_mb = 4096.0;  // estimated peak memory per job (service/job_cost.hpp), MiB
  storage::SenderQuota quota;         // queued jobs and their estimated seconds, per sender
  double progress_hz = 5.0;  // progress messages per second and job, at most
  std::string executor = "local";  // local: worker threads run the jobs; slurm: workers dispatch them to Slurm
  remote::SlurmOptions slurm;      // with executor "slurm"
  std::string auth_secret_file;  // empty: messages are not authenticated (a warning at start)
  AuthReads auth_reads = AuthReads::owner;
};

// Throws std::invalid_argument naming the key and the admissible range.
ServerConfig server_config_from_file(const std::string& path, ServerConfig base = {});
// Applies --database, --lcm-url, --workers, --max-job-seconds, --max-job-iterations,
// --max-job-memory-mb, --max-queued-jobs, --max-queued-hours, --progress-hz (after --config
// FILE); throws std::invalid_argument on unknown or bad flags.
ServerConfig server_config_from_args(const std::vector<std::string>& args);
int effective_workers(const ServerConfig& c);

inline constexpr const char* kServerUsage = R"(usage: cycloptd [--config FILE.json] [--database FILE] [--lcm-url URL]
                [--workers N] [--max-job-seconds S] [--max-job-iterations N]
                [--max-job-memory-mb MB] [--max-queued-jobs N]
                [--max-queued-hours H] [--progress-hz HZ]
                [--executor local|slurm] [--slurm-spool DIR]

The cyclopt job server: queues jobs submitted over LCM, runs them on one worker
per core, stores every solved point in SQLite (WAL) and publishes progress.
SIGTERM / SIGINT stop it gracefully: running jobs are checkpointed (their stored
points kept) and resume at the next start.

  --config FILE          JSON file with any of: database, lcm_url, workers,
                         max_job_seconds, max_job_iterations, max_job_memory_mb,
                         max_queued_jobs, max_queued_hours, progress_hz,
                         executor, slurm, auth_secret_file, auth_reads (owner: a
                         key reads only its own jobs, admin keys all; any: every
                         key reads every job) (flags given after it override it;
                         auth_secret_file and auth_reads are read from the
                         config file only)
  --database FILE        results database (default cyclopt.db; created if
                         missing)
  --lcm-url URL          LCM provider, e.g. udpm://239.255.76.67:7667?ttl=0
                         (default: LCM's)
  --workers N            worker threads, 1..256 (default: number of cores)
  --max-job-seconds S    per-job wall-time cap, (0, 604800] (default 3600); a
                         job whose estimated time exceeds it is rejected at
                         submission
  --max-job-iterations N per-job iteration cap, 1..1e9 (default 1e7)
  --max-job-memory-mb MB a job whose estimated peak memory exceeds it is
                         rejected, [16, 1048576] (default 4096)
  --max-queued-jobs N    queued jobs per sender (the authenticated key, or for
                         unauthenticated clients the sending host), 1..1e6
                         (default 100)
  --max-queued-hours H   estimated hours of queued jobs per sender, (0, 1e6]
                         (default 168)
  --progress-hz HZ       progress messages per job and second, [0.1, 100]
                         (default 5)
  --executor E           local (default: the workers compute the jobs) or slurm
                         (each worker dispatches its job to Slurm as a batch job
                         of cyclopt-worker; further settings in the config
                         file's "slurm" object, see docs/service.md)
  --slurm-spool DIR      directory shared with the cluster nodes (required with
                         slurm)
Exit codes: 0 clean shutdown, 1 bad usage or config, 2 database or LCM failure.
)";

}  // namespace cyclopt::server
