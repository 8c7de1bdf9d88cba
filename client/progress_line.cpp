#include "progress_line.hpp"

#include <cmath>
#include <cstdio>

namespace cyclopt::client {

std::string duration_text(double seconds) {
  if (!(seconds >= 0.0) || !std::isfinite(seconds)) return "?";
  char buf[32];
  const long s = std::lround(seconds);
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%ld s", s);
  else if (s < 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  return buf;
}

std::string progress_line(const cyclopt_lcm::job_progress_t& p, std::size_t width) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "job %lld", static_cast<long long>(p.job_id));
  std::string line = buf;
  if (p.points_total > 0) {
    std::snprintf(buf, sizeof buf, " %3.0f%% %d/%d", std::isfinite(p.percent) ? p.percent : 0.0, p.points_done, p.points_total);
    line.append(buf);
  }
  // Time and ETA before the phase: a narrow terminal cuts the phase's end, not the ETA.
  line.append(" | ").append(duration_text(p.elapsed_seconds)).append(", ETA ").append(duration_text(p.eta_seconds));
  if (!p.phase.empty()) {
    line.append(" | ").append(p.phase);
    if (p.phase_total > 0) {
      std::snprintf(buf, sizeof buf, " %d/%d", p.phase_done, p.phase_total);
      line.append(buf);
    }
  } else if (!p.message.empty()) {
    line.append(" | ").append(p.message);
  }
  if (std::isfinite(p.best_objective)) {
    std::snprintf(buf, sizeof buf, " | best %.6g", p.best_objective);
    line.append(buf);
  } else if (std::isfinite(p.objective)) {
    std::snprintf(buf, sizeof buf, " | objective %.6g", p.objective);
    line.append(buf);
  }
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
