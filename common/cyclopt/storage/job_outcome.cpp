#include "cyclopt/storage/job_outcome.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cyclopt::storage {
namespace {

constexpr std::size_t kNamedPoints = 8;  // the summary names at most this many points

// "speed 1.3 (max_iterations)", or "curve 2 point 4 (...)" without a parameter.
std::string point_text(const RequiredPoint& p) {
  char b[64];
  if (std::isfinite(p.parameter))
    std::snprintf(b, sizeof b, "%s %g", p.parameter_name.empty() ? "parameter" : p.parameter_name.c_str(), p.parameter);
  else
    std::snprintf(b, sizeof b, "curve %d point %d", p.key.curve_index, p.key.point_index);
  return std::string(b) + " (" + p.status + ")";
}

}  // namespace

JobOutcome judge_job_outcome(const std::vector<RequiredPoint>& points, std::optional<int> points_total) {
  JobOutcome o;
  o.expected = std::max(points_total.value_or(0), static_cast<int>(points.size()));
  std::vector<const RequiredPoint*> failed;
  for (const RequiredPoint& p : points) {
    if (is_converged_status(p.status))
      ++o.converged;
    else
      failed.push_back(&p);
  }
  const int missing = o.expected - static_cast<int>(points.size());
  if (o.converged == o.expected && o.expected > 0) return o;
  o.state = o.converged == 0 ? JobState::failed : JobState::incomplete;
  o.summary = o.expected == 0 ? "no point was found"
                              : std::to_string(o.converged) + " of " + std::to_string(o.expected) + " points converged";
  if (!failed.empty()) {
    o.summary += "; not converged: ";
    for (std::size_t i = 0; i < std::min(failed.size(), kNamedPoints); ++i)
      o.summary += (i ? ", " : "") + point_text(*failed[i]);
    if (failed.size() > kNamedPoints) o.summary += " and " + std::to_string(failed.size() - kNamedPoints) + " more";
  }
  if (missing > 0) o.summary += "; " + std::to_string(missing) + " not stored";
  return o;
}

}  // namespace cyclopt::storage
