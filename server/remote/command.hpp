#pragma once
// Runs a program (no shell: arguments are passed as they are) and collects its standard output.

#include <string>
#include <vector>

namespace cyclopt::server::remote {

struct CommandResult {
  int exit_code = -1;  // -1: could not be started or was killed by a signal
  std::string output;  // standard output (standard error goes to ours)
};

CommandResult run_command(const std::vector<std::string>& argv);

}  // namespace cyclopt::server::remote
