#pragma once
// The speed sweep family of the result contract (studies/speed_sweep.hpp, seed 001 chapter 9):
// what a sweep job stores on curve 0, one row per grid speed, beside the walker point of the best
// point there (walker_point_record.hpp) or, where no step of the sweep found one (status "not
// found"), on its own.

#include "cyclopt/records/json_fields.hpp"
#include "cyclopt/records/point_record.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace cyclopt::records {

// The work of the attempt that stored the row (a resumed sweep takes finished solves and runs
// over from its checkpoints).
struct SweepAttemptRecord {
  int multistart_solves = 0, resumed_solves = 0;
  int computed_runs = 0, resumed_runs = 0;
  bool operator==(const SweepAttemptRecord&) const = default;
};

struct SweepBestRecord {
  std::optional<std::string> found_by;  // which sweep step found the point (studies::describe)
  std::optional<std::string> reason;    // why there is none
  double sweep_seconds = kUnset;        // wall time of the whole sweep
  int curves = 0;                       // solution curves the sweep followed
  std::string closure;                  // how the envelope's closure ended (studies::describe)
  int closure_passes = 0;               // closure passes that improved this speed's best point
  std::optional<double> seed_spread;    // spread of the seeds' own best f at this speed (several seeds)
  SweepAttemptRecord attempt;
  bool operator==(const SweepBestRecord&) const = default;
};

void to_json(nlohmann::json& j, const SweepBestRecord& b);
void from_json(const nlohmann::json& j, SweepBestRecord& b);  // throws RecordError naming the field

template <>
inline constexpr bool is_point_values<SweepBestRecord> = true;

}  // namespace cyclopt::records
