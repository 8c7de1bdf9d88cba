#pragma once
// Settings of the Slurm executor (cycloptd --executor slurm; the config file's "slurm" object).

#include <string>

namespace cyclopt::server::remote {

struct SlurmOptions {
  std::string spool;          // directory every node sees; one subdirectory per job (required)
  std::string worker;         // cyclopt-worker program (default: beside cycloptd)
  std::string partition;      // sbatch --partition (empty: the cluster's default)
  std::string account;        // sbatch --account (empty: none)
  int cpus_per_unit = 1;      // sbatch --cpus-per-task, 1..1024
  int time_limit_minutes = 0; // sbatch --time cap per unit (0: from the job's wall-time limit)
  int max_submissions = 4;    // a unit that fails without a result is submitted at most this often, 1..100
  double poll_seconds = 0.5;  // how often the spool and squeue are read, [0.05, 60]
};

}  // namespace cyclopt::server::remote
