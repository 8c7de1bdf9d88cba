#pragma once
// What a benchmark ran on: printed at the top of every committed results table.

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

inline std::string machine_line() {
  return cpu_model() + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads";
}

}  // namespace cyclopt::bench
