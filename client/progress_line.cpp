#include "progress_line.hpp"

#include <cmath>
#include <cstdio>

namespace cyclopt::client {

std::string percent_text(double percent, bool lower_bound) {
  if (!std::isfinite(percent)) return "?";
  char buf[16];
  std::snprintf(buf, sizeof buf, "%s%.0f%%", lower_bound ? ">=" : "", std::floor(percent));
  return buf;
}

std::string progress_line(const cyclopt_lcm::job_progress_t& p, std::size_t width) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "job %lld %4s", static_cast<long long>(p.job_id),
                percent_text(p.percent, p.percent_is_lower_bound).c_str());
  std::string head = buf;
  if (p.points_total > 0) {
    std::snprintf(buf, sizeof buf, " %d/%d", p.points_done, p.points_total);
    head.append(buf);
  }
  head.append(" | ").append(duration_text(p.elapsed_seconds)).append(", ETA ").append(duration_text(p.eta_seconds));
  std::string phase;
  if (!p.phase.empty()) {
    phase = " | " + p.phase;
    if (p.phase_total > 0) {
      std::snprintf(buf, sizeof buf, " %d/%d", p.phase_done, p.phase_total);
      phase.append(buf);
    }
  } else if (!p.message.empty()) {
    phase = " | " + p.message;
  }
  std::string best;
  if (std::isfinite(p.best_objective)) {
    std::snprintf(buf, sizeof buf, " | best %.6g", p.best_objective);
    best = buf;
  } else if (std::isfinite(p.objective)) {
    std::snprintf(buf, sizeof buf, " | objective %.6g", p.objective);
    best = buf;
  }
  // A narrow terminal cuts the phase, never the best value at the end.
  const std::size_t fixed = head.size() + best.size();
  if (fixed + phase.size() > width && fixed + 6 <= width) phase = phase.substr(0, width - fixed - 3) + "...";
  std::string line = head + phase + best;
  if (line.size() > width) {
    line.resize(width > 3 ? width - 3 : width);
    if (width > 3) line.append("...");
  }
  return line;
}

bool LogThrottle::due(const cyclopt_lcm::job_progress_t& p, std::chrono::steady_clock::time_point now) {
  if (printed_ && p.phase == phase_ && now - last_ < interval_) return false;
  printed_ = true;
  phase_ = p.phase;
  last_ = now;
  return true;
}

}  // namespace cyclopt::client
