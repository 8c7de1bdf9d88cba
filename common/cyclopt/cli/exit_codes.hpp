#pragma once
// The exit codes of every cyclopt program (cyclopt, cyclopt-foot, cyclopt-giant-swing, cycloptd,
// cyclopt-worker): one table, printed by each program's --help and in docs/results.md ("Exit codes").

namespace cyclopt::cli {

enum ExitCode : int {
  kExitOk = 0,
  kExitUsage = 1,       // bad command line: unknown option, missing or malformed argument
  kExitRejected = 2,    // invalid input (a spec, foot or task names the field), not found, job failed or cancelled
  kExitNoAnswer = 3,    // no answer from cycloptd within --timeout, or a job still running at --watch-timeout
  kExitResource = 4,    // a file, the database or the LCM transport cannot be read, written or opened
  kExitIncomplete = 5,  // the job ended but some of its required points are missing or did not converge
};

// The table as the programs' --help prints it.
inline constexpr const char* kExitCodeTable =
    "Exit codes (all cyclopt programs): 0 ok; 1 bad usage; 2 invalid input, not\n"
    "found, job failed or cancelled; 3 no answer from the server in time; 4 file,\n"
    "database or LCM error; 5 job incomplete (some required points missing or not\n"
    "converged).\n";

}  // namespace cyclopt::cli
