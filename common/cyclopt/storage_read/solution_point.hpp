#pragma once
// One solved point of a job as it is committed to the solutions table (and, optionally, its
// trajectory). (curve_index, point_index) identifies the point within its job. Its values and
// trajectory are set from records of the result contract only (records/point_record.hpp).

#include "cyclopt/records/point_record.hpp"

#include <nlohmann/json.hpp>

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

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

  // What the job kind reports: records of the result contract (records/), their members merged
  // into one object (a later record's member replaces an earlier one's of the same name).
  template <records::PointValues... Records>
  void set_values(const Records&... records) {
    values_ = nlohmann::json::object();
    (values_.update(nlohmann::json(records)), ...);
  }
  // Stored as a "json" trajectory blob.
  template <records::PointTrajectory Record>
  void set_trajectory(const Record& record) {
    trajectory_ = nlohmann::json(record);
  }
  // A point whose values and trajectory records wrote, carried over as they are (read back from a
  // work unit's spool, server/remote/unit_spool.hpp).
  void carry(nlohmann::json values, std::optional<nlohmann::json> trajectory) {
    values_ = std::move(values);
    trajectory_ = std::move(trajectory);
  }
  const nlohmann::json& values() const { return values_; }
  const std::optional<nlohmann::json>& trajectory() const { return trajectory_; }

 private:
  nlohmann::json values_ = nlohmann::json::object();
  std::optional<nlohmann::json> trajectory_;
};

}  // namespace cyclopt::storage
