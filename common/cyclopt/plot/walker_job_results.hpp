#pragma once
// The solved points of one walker job as the figures need them, read from a job document: the
// JSON `cyclopt export` writes (job row with spec, events, curves, solutions, trajectories),
// whether it came from the server, a database file or an exported file. Values and trajectories
// are read through the result contract (records/), so the figures see typed fields only.

#include "cyclopt/records/gait_records.hpp"
#include "cyclopt/records/sensitivity_records.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cyclopt::plot {

struct GaitPoint {
  double speed = 0;              // requested mean speed (the point's parameter), m/s
  std::string status;            // solver termination or "ok" / "no real solution"
  bool converged = false;        // a real gait and, if optimised, a successful solve
  records::GaitRecord gait;      // values.gait (not real when the point has none)
  std::optional<records::GaitTrajectoryRecord> trajectory;  // none when none was stored
  std::optional<records::KktSensitivitiesRecord> sensitivities;  // values.sensitivities of an optimum
};

struct WalkerJobResults {
  std::int64_t id = 0;
  std::string label;  // for legends: the spec's name, else "job N: foot, objective"
  nlohmann::json spec;
  jobs::WalkerJob job;  // parsed spec: foot, model constants, objective
  std::vector<GaitPoint> points;  // curve 0, in point order
};

// Throws std::invalid_argument when the document is not a walker job of a task with gaits, and
// records::RecordError when a stored point does not follow the contract.
WalkerJobResults walker_job_results(const nlohmann::json& document);

// The gaits of one curve of a job document in point order (values a records::WalkerPointRecord,
// trajectories a records::GaitTrajectoryRecord): curve 0 of a walker job, a sweep curve of a
// foot_design job. Throws records::RecordError when a stored point does not follow the contract.
std::vector<GaitPoint> gait_points(const nlohmann::json& document, int curve);

// The converged point whose speed is closest to `speed` (any converged point when NaN) that has a
// trajectory; nullptr if there is none.
const GaitPoint* point_near(const WalkerJobResults& r, double speed);

}  // namespace cyclopt::plot
