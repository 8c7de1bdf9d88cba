#pragma once
// How `cyclopt watch` / `submit --watch` show a running job's progress (issue 17 item 3): one line
// per report, e.g.
//   job 3  29% 6/21 | 1:12, ETA 2:30 | continuation run 2 from 1.3 m/s upwards, curve 1 5/10 | best 0.02263
// (the server's percentage, service/progress_meter.hpp: ">=29%" while the ETA is unknown; the
// points stored of those announced; the phase's steps), rewritten in place on a terminal, and in
// a log (stderr not a terminal) printed when the phase changes and otherwise at most every few
// seconds.

#include <cyclopt_lcm/job_progress_t.hpp>

#include "cyclopt/service/progress_meter.hpp"

#include <chrono>
#include <cstddef>
#include <string>

namespace cyclopt::client {

// The line, at most `width` characters: a long phase is cut with "..." so the best value stays.
std::string progress_line(const cyclopt_lcm::job_progress_t& progress, std::size_t width);

// "42%" (rounded down: 99.6 is not "100%"), ">=42%" for a lower bound, "?" for NaN.
std::string percent_text(double percent, bool lower_bound);

// "42 s", "3:05", "1:02:05"; "?" for NaN or negative (service/progress_meter.hpp).
inline std::string duration_text(double seconds) { return service::clock_text(seconds); }

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
