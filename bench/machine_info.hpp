#pragma once
// What a benchmark ran on: printed at the top of every committed results table.

#include "cyclopt/nlp/spare_core.hpp"

#include <sys/resource.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

namespace cyclopt::bench {

inline std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

// CYCLOPT_SPARE_CORES=never (or always) sets nlp::SpareCoreRule for the benchmark, to measure what
// the helper threads of nlp/spare_core.hpp gain; the line names the rule in force.
inline std::string spare_core_rule_from_environment() {
  const char* rule = std::getenv("CYCLOPT_SPARE_CORES");
  const std::string name = rule ? rule : "measured";
  if (name == "never") nlp::set_spare_core_rule(nlp::SpareCoreRule::never);
  else if (name == "always") nlp::set_spare_core_rule(nlp::SpareCoreRule::always);
  else return "spare cores measured";
  return "spare cores " + name + " (CYCLOPT_SPARE_CORES)";
}

// Also applies CYCLOPT_SPARE_CORES (above): every benchmark prints this line.
inline std::string machine_line() {
  return cpu_model() + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads, " +
         spare_core_rule_from_environment();
}

// The machine is shared: every timing is printed with the load average (1, 5, 15 min) beside it.
inline std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  in >> one >> five >> fifteen;
  return "load average " + one + " " + five + " " + fifteen;
}

// User + system CPU seconds of this process so far (all threads): less sensitive to the load
// than wall time.
inline double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

}  // namespace cyclopt::bench
