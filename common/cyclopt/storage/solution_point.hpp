#pragma once
// One solved point of a job as it is committed to the solutions table (and, optionally, its
// trajectory). (curve_index, point_index) identifies the point within its job.

#include <nlohmann/json.hpp>

#include <limits>
#include <optional>
#include <string>

namespace cyclopt::storage {

struct PointKey {
  int curve_index = 0;
  int point_index = 0;
  auto operator<=>(const PointKey&) const = default;
};

struct SolutionPoint {
  PointKey key;
  double parameter = std::numeric_limits<double>::quiet_NaN();  // NaN -> NULL
  double objective = std::numeric_limits<double>::quiet_NaN();
  double constraint_violation = std::numeric_limits<double>::quiet_NaN();
  int iterations = 0;
  std::string status = "ok";          // e.g. converged, max_iterations, infeasible
  nlohmann::json values = nlohmann::json::object();  // whatever the job kind reports
  std::optional<nlohmann::json> trajectory;          // stored as a "json" trajectory blob
};

}  // namespace cyclopt::storage
