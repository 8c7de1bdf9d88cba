#pragma once
// One solved point of a job as it is committed to the solutions table (and, optionally, its
// trajectory). (curve_index, point_index) identifies the point within its job.

#include <nlohmann/json.hpp>

#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace cyclopt::storage {

struct PointKey {
  int curve_index = 0;
  int point_index = 0;
  auto operator<=>(const PointKey&) const = default;
};

// The statuses of a point that is a solution: "ok" (an evaluation or computation that succeeded),
// "converged" and "acceptable" (nlp::Termination). Everything else (max_iterations, infeasible,
// not found, ...) is a point that did not converge.
inline bool is_converged_status(std::string_view status) {
  return status == "ok" || status == "converged" || status == "acceptable";
}

struct SolutionPoint {
  PointKey key;
  double parameter = std::numeric_limits<double>::quiet_NaN();  // NaN -> NULL
  double objective = std::numeric_limits<double>::quiet_NaN();
  double constraint_violation = std::numeric_limits<double>::quiet_NaN();
  int iterations = 0;
  std::string status = "ok";          // e.g. converged, max_iterations, infeasible (is_converged_status)
  // Whether the point is one the job was asked for (a sweep's best point per speed, a
  // continuation's grid values) and so counts for the job's outcome (job_outcome.hpp), or a by-product
  // (a sweep's continuation runs, a continuation's steps between grid values).
  bool required = true;
  nlohmann::json values = nlohmann::json::object();  // whatever the job kind reports
  std::optional<nlohmann::json> trajectory;          // stored as a "json" trajectory blob
};

}  // namespace cyclopt::storage
