#pragma once
// The solved points of one walker job as the figures need them, read from a job document: the
// JSON `cyclopt export` writes (job row with spec, events, curves, solutions, trajectories),
// whether it came from the server, a database file or an exported file. The walker, values and
// trajectories are read through the result contract (records/), so the figures see typed fields only.

#include "cyclopt/foot/foot_spec.hpp"
#include "cyclopt/records/gait_records.hpp"
#include "cyclopt/records/sensitivity_records.hpp"
#include "cyclopt/records/walker_setup_record.hpp"
#include "cyclopt/walker/walker_model.hpp"

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
  // A sweep searched with several seeds: (max - min) / min of the seeds' own best f here
  // (records::SweepBestRecord::seed_spread).
  std::optional<double> seed_spread;
};

// The name of joint j of q_b (eq. 5.3; 4 joints for point feet, 6 with feet), as the rows of a
// stored trajectory's torque (and q rows 1 + j) hold them: "H1 stance hip", ..., "A2 swing ankle".
const char* joint_name(int joint);

// The walker a job's points were solved on, from its setup record.
struct StoredWalker {
  records::WalkerSetupRecord setup;
  foot::FootSpec foot;
  walker::WalkingConstants constants;  // P and M of the setup, the model's defaults where it has none
  walker::WalkerModel<double> model() const { return walker::make_walker_model(foot, constants); }
};

// The setup record of a job document's stored spec (the resolved spec where the job has one).
// Throws records::RecordError, or SpecError for a foot that is no preset or valid foot spec.
StoredWalker stored_walker(const nlohmann::json& spec);
// That stored spec.
const nlohmann::json& stored_spec(const nlohmann::json& document);

// A solution curve a sweep followed (curve c >= 1 of the store, as `cyclopt query` numbers it).
struct SolutionCurve {
  int curve = 0;
  std::string name;
  std::vector<GaitPoint> points;  // in point order
};

struct WalkerJobResults {
  std::int64_t id = 0;
  std::string label;  // for legends: the spec's name, else "job N: foot, objective"
  nlohmann::json spec;  // as stored (the resolved spec where the job has one)
  StoredWalker walker;
  std::vector<GaitPoint> points;  // curve 0, in point order
  std::vector<SolutionCurve> curves;  // the stored curves after 0 (a sweep's solution curves)
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
