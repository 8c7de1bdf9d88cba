#pragma once
// Short usage on a bad command line: the error, the synopsis (the usage text up to its first blank
// line) and where the rest is, instead of the whole --help text.

#include <string>

namespace cyclopt::cli {

// "PROGRAM: MESSAGE\nSYNOPSIS\nRun 'PROGRAM --help' for all options.\n"
std::string short_usage(const std::string& program, const std::string& message, const std::string& usage);

}  // namespace cyclopt::cli
