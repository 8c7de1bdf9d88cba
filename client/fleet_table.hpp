#pragma once
// The fleet of jobs as `cyclopt list` and `cyclopt top` show it (issue 53, docs/watching-jobs.md):
// one line per job, built from the `jobs` query rows (their stored progress) and, in `top`, updated
// from the live LCM progress messages. The columns, left to right:
//   list: ID NAME KIND FOOT STATE PROG BEST RUN SUBMITTED STARTED ENDED
//   top:  ID STATE PROG BEST ETA RUN NAME KIND FOOT STARTED PHASE
// When the lines are wider than the terminal, columns are dropped from the right (in top the
// PHASE is first cut to what is left), never ID, STATE, PROG or BEST; only if those alone do
// not fit is the line cut. Long names are cut with "~". Times are ISO 8601 local time to the
// minute ("2026-12-06T17:03"; list's STARTED and ENDED "17:03" on the day of SUBMITTED).

#include <cyclopt_lcm/job_progress_t.hpp>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace cyclopt::client {

struct FleetJob {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::int64_t id = 0;
  std::string name, kind, foot, state, phase;
  double percent = kNaN;             // the server's (service/progress_meter.hpp)
  bool percent_lower_bound = false;
  double eta_seconds = kNaN;
  double best_objective = kNaN;
  double run_seconds = kNaN;
  double submitted_at = kNaN, started_at = kNaN, finished_at = kNaN;  // Unix seconds
};

// A row of the `jobs` query (storage_read/result_queries.hpp).
FleetJob fleet_job(const nlohmann::json& row);
// The job with a live progress message of it applied (`top`).
void apply_progress(FleetJob& job, const cyclopt_lcm::job_progress_t& progress);

enum class FleetView { list, top };

// The header and one line per job, each at most `width` characters.
std::vector<std::string> fleet_table(const std::vector<FleetJob>& jobs, FleetView view, std::size_t width);

// "2026-12-06T17:03" in local time; "-" for NaN.
std::string local_iso_minutes(double unix_seconds);
// "2026-12-06T17:03:12+01:00" in local time; "-" for NaN.
std::string local_iso_time(double unix_seconds);

}  // namespace cyclopt::client
