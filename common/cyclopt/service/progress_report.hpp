#pragma once
// What a job kind tells JobContext::report_progress(); fields it does not have stay NaN / -1.
// The context adds the job id, percentage and ETA, and rate-limits publication.

#include <limits>
#include <string>

namespace cyclopt::service {

struct ProgressReport {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  int iteration = -1;                  // solver iteration within the current point
  double objective = kNaN;
  double constraint_violation = kNaN;
  double parameter = kNaN;             // sweep / continuation parameter of the current point
  int curve_id = -1;
  int points_done = 0;                 // points stored so far, including ones from earlier attempts
  int points_total = -1;               // -1: unknown
  std::string message{};
  // The phase of the job ("multistart at 1.3 m/s", "continuation run 2 from 1.3 m/s upwards,
  // curve 0") and how far it is, the best objective found so far, and the kind's own ETA from
  // measured rates (NaN: the context estimates it from points_done).
  std::string phase{};
  int phase_done = -1;
  int phase_total = -1;
  double best_objective = kNaN;
  double eta_seconds = kNaN;
  std::string unit{};  // the work unit reporting (set by UnitJobContext); "": the job itself
};

}  // namespace cyclopt::service
