#pragma once
// A stored walker point's values (storage::SolutionPoint::values) as the walker job kinds write
// them (service/walker_points.hpp): the gait, the solve that produced it and, for a continuation
// point, the step of seed 001 Algorithm 2 that reached it. Job kinds add their own members beside
// these (a sweep's found_by, a multistart's reached_by_starts); from_json ignores them.

#include "cyclopt/records/gait_records.hpp"
#include "cyclopt/records/point_record.hpp"
#include "cyclopt/records/sensitivity_records.hpp"
#include "cyclopt/records/solver_record.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace cyclopt::records {

// Stored flat beside the gait (curve_id, on_grid, ...), as continuation::CurvePoint has them.
struct ContinuationStepRecord {
  int curve_id = 0;
  bool on_grid = false, converged = false;
  int predictor_attempts = 0, predictor_steps = 0;
  double kappa = kUnset;  // contraction estimate of the corrector (absent when not measured)
  double trust_region = kUnset;
  double point_seconds = kUnset;
  bool operator==(const ContinuationStepRecord&) const = default;
};

struct WalkerPointRecord {
  std::optional<GaitRecord> gait;             // none for a speed no sweep step reached ("not found")
  std::optional<SolverRecord> solver;         // optimised points
  std::optional<std::string> start;           // where the solve or evaluation started
  std::optional<double> start_objective;      // the objective there
  std::optional<ContinuationStepRecord> continuation;
  std::vector<double> x;                      // the NLP variables (empty: not stored)
  std::optional<KktSensitivitiesRecord> sensitivities;  // of a converged optimum (optimise, sensitivity jobs)
  bool operator==(const WalkerPointRecord&) const = default;
};

// The gait counts as solved when it is real and its solve (if any) succeeded.
bool solved(const WalkerPointRecord& p);

// Flat: the members beside each other in one object (also a sweep checkpoint's curve point,
// jobs/walker/sweep_checkpoints.hpp).
void to_json(nlohmann::json& j, const ContinuationStepRecord& c);
void from_json(const nlohmann::json& j, ContinuationStepRecord& c);  // throws RecordError naming the field
void to_json(nlohmann::json& j, const WalkerPointRecord& p);
void from_json(const nlohmann::json& j, WalkerPointRecord& p);  // throws RecordError naming the field

template <>
inline constexpr bool is_point_values<WalkerPointRecord> = true;

}  // namespace cyclopt::records
