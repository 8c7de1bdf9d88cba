#pragma once
// How far a running job is (issue 53 item 3), from what its kind reports (progress_report.hpp):
// the percentage and ETA every progress message, `cyclopt list/top` and the store show.
//   - ETA: the kind's own (measured rates over all its phases), else one from the points
//     (this attempt's seconds per point stored times the points left), else unknown. A value
//     repeated unchanged counts down from when it was first given; once it has run out the ETA
//     is unknown ("?"), never a constant that expires.
//   - Work units (unit_job_context.hpp) that give ETAs of their own, possibly several at once:
//     the job's ETA is the longest of the running units' plus the units not begun, in rounds of
//     as many as run at once, at the mean duration of the units ended (before one ended, of the
//     running ones as estimated); unknown while a running unit's is.
//   - percent: the share of the run time so far in the estimated total, elapsed / (elapsed + ETA);
//     while no ETA was ever known, the share of points stored. It never goes down (a grown
//     estimate holds the percentage until the run catches up), stays at most kRunningCap while
//     the job runs and is 100 only once the job ended (finish).
//   - lower_bound: the ETA is unknown now, so the percentage is the one reached, not an estimate.
// Not thread-safe: the worker's context calls it under its progress lock.

#include "cyclopt/service/progress_report.hpp"

#include <map>
#include <string>

namespace cyclopt::service {

struct ProgressReading {
  double percent = 0.0;
  double eta_seconds = ProgressReport::kNaN;
  bool lower_bound = true;
};

class ProgressMeter {
 public:
  static constexpr double kRunningCap = 99.0;  // displayed as "99%", never "100%", while running
  // A unit not heard from for this long (a remote unit whose end was not seen) no longer counts.
  static constexpr double kUnitSilenceSeconds = 600.0;

  // points_at_start: points stored by earlier attempts (their time is not this attempt's rate).
  explicit ProgressMeter(int points_at_start = 0) : points_at_start_(points_at_start) {}

  // `report` with its points_total resolved (announced total if the kind gave none); job_seconds:
  // the job's run time over all attempts, attempt_seconds: this attempt's.
  ProgressReading read(const ProgressReport& report, double job_seconds, double attempt_seconds);
  // The job splits into `total` work units; unit_ended: one of them returned.
  void units(int total) { units_total_ = total; }
  void unit_ended(const std::string& unit, double job_seconds);
  // The job ended: 100 % if it ran to its end (done or incomplete), else the percentage reached.
  ProgressReading finish(bool ran_to_end);

 private:
  struct Estimate {  // the last ETA a source gave and the job second it was given at
    double eta = ProgressReport::kNaN;
    double at = 0.0;
    double seen = 0.0;  // its last report
    void give(double value, double now);
    double left(double now) const { return eta - (now - at); }  // counted down; <= 0 or NaN: unknown
  };
  double units_eta(double job_seconds) const;

  int points_at_start_;
  double percent_ = 0.0;
  bool eta_seen_ = false;       // any ETA was ever known
  bool unit_etas_ = false;      // units give ETAs of their own
  Estimate job_;                // the kind's ETA, or the points' (key: the job)
  std::map<std::string, Estimate> running_;           // per unit that gave an ETA and has not ended
  std::map<std::string, double> unit_began_;          // job second of each unit's first report
  int units_total_ = 0, units_ended_ = 0, units_timed_ = 0;
  double ended_unit_seconds_ = 0.0;                   // summed over the units_timed_ ended units
};

// "42 s", "3:05", "1:02:05"; "?" for NaN or negative.
std::string clock_text(double seconds);

}  // namespace cyclopt::service
