#include "cyclopt/service/progress_meter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cyclopt::service {

void ProgressMeter::Estimate::give(double value, double now) {
  seen = now;
  if (std::isnan(value) || value != eta) {  // a new estimate (a repeated one counts down)
    eta = value;
    at = now;
  }
}

double ProgressMeter::units_eta(double now) const {
  double longest = 0.0, unit_seconds = 0.0;
  int running = 0;
  for (const auto& [unit, e] : running_) {
    if (now - e.seen > kUnitSilenceSeconds) continue;
    const double left = e.left(now);
    if (!(left > 0.0)) return ProgressReport::kNaN;
    longest = std::max(longest, left);
    const auto began = unit_began_.find(unit);
    unit_seconds += now - (began != unit_began_.end() ? began->second : e.at) + left;
    ++running;
  }
  if (running == 0) return ProgressReport::kNaN;
  unit_seconds = units_timed_ > 0 ? ended_unit_seconds_ / units_timed_ : unit_seconds / running;
  const int waiting = std::max(0, units_total_ - units_ended_ - running);
  return longest + std::ceil(static_cast<double>(waiting) / running) * unit_seconds;
}

ProgressReading ProgressMeter::read(const ProgressReport& r, double job_seconds, double attempt_seconds) {
  if (!r.unit.empty()) unit_began_.emplace(r.unit, job_seconds);
  double eta = r.eta_seconds;
  if (!r.unit.empty() && std::isfinite(eta)) unit_etas_ = true;
  if (unit_etas_ && !r.unit.empty()) {
    running_[r.unit].give(eta, job_seconds);
    eta = units_eta(job_seconds);
  } else {
    const int solved_now = r.points_done - points_at_start_;
    if (!std::isfinite(eta) && solved_now > 0 && r.points_total > 0)
      eta = attempt_seconds / solved_now * std::max(0, r.points_total - r.points_done);
    job_.give(eta, job_seconds);
    eta = job_.left(job_seconds);
  }
  ProgressReading out;
  if (eta > 0.0) out.eta_seconds = eta;
  double share = percent_;
  if (std::isfinite(out.eta_seconds)) {
    eta_seen_ = true;
    share = 100.0 * job_seconds / (job_seconds + out.eta_seconds);
  } else if (!eta_seen_ && r.points_total > 0) {
    share = 100.0 * r.points_done / r.points_total;
  }
  percent_ = std::clamp(std::max(percent_, share), 0.0, kRunningCap);
  out.percent = percent_;
  out.lower_bound = !std::isfinite(out.eta_seconds);
  return out;
}

void ProgressMeter::unit_ended(const std::string& unit, double job_seconds) {
  ++units_ended_;
  if (running_.erase(unit) > 0) {
    ended_unit_seconds_ += job_seconds - unit_began_[unit];
    ++units_timed_;
  }
}

ProgressReading ProgressMeter::finish(bool ran_to_end) {
  if (ran_to_end) percent_ = 100.0;
  return {percent_, ran_to_end ? 0.0 : ProgressReport::kNaN, !ran_to_end};
}

std::string clock_text(double seconds) {
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

}  // namespace cyclopt::service
