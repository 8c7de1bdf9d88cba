#include "cyclopt/cli/usage_text.hpp"

namespace cyclopt::cli {

std::string short_usage(const std::string& program, const std::string& message, const std::string& usage) {
  const std::size_t blank = usage.find("\n\n");
  const std::string synopsis = blank == std::string::npos ? usage : usage.substr(0, blank + 1);
  return program + ": " + message + "\n" + synopsis + "Run '" + program + " --help' for all options.\n";
}

}  // namespace cyclopt::cli
