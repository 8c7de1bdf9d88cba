#pragma once
// What a job that ran to its end achieved, judged from its stored required points
// (SolutionPoint::required) against the number it announced: done when every one is stored and
// converged, failed when none converged, incomplete otherwise. The summary names the points that
// did not converge (with their status) and how many are missing, so "done" never hides a solve
// that ended at max_iterations.

#include "cyclopt/storage_read/job_state.hpp"
#include "cyclopt/storage_read/result_reader.hpp"

#include <optional>
#include <string>
#include <vector>

namespace cyclopt::storage {

struct JobOutcome {
  JobState state = JobState::done;
  int expected = 0;   // announced points (or the required points stored, if more or unannounced)
  int converged = 0;  // required points with a converged status
  std::string summary;  // "" when done; otherwise what is missing or did not converge
};

JobOutcome judge_job_outcome(const std::vector<RequiredPoint>& points, std::optional<int> points_total);

}  // namespace cyclopt::storage
