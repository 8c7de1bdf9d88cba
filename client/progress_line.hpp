#pragma once
// How `cyclopt watch` / `submit --watch` show a running job's progress (issue 17 item 3): one line
// per report, e.g.
//   job 3  29% 6/21 | 1:12, ETA 2:30 | continuation run 2 from 1.3 m/s upwards, curve 0 5/10 | best 0.02263
// rewritten in place on a terminal, and in a log (stderr not a terminal) printed when the phase
// changes and otherwise at most every few seconds.

#include <cyclopt_lcm/job_progress_t.hpp>

#include <chrono>
#include <cstddef>
#include <string>

namespace cyclopt::client {

// The line, at most `width` characters (longer lines are cut with "...").
std::string progress_line(const cyclopt_lcm::job_progress_t& progress, std::size_t width);

// "42 s", "3:05", "1:02:05"; "?" for NaN or negative.
std::string duration_text(double seconds);

// For a log: whether a report gets a line.
class LogThrottle {
 public:
  explicit LogThrottle(std::chrono::steady_clock::duration interval) : interval_(interval) {}
  bool due(const cyclopt_lcm::job_progress_t& progress, std::chrono::steady_clock::time_point now);

 private:
  std::chrono::steady_clock::duration interval_;
  std::chrono::steady_clock::time_point last_{};
  bool printed_ = false;
  std::string phase_;
};

}  // namespace cyclopt::client
