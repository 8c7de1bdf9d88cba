#pragma once
// The foot_comparison family of the result contract (service/foot_comparison_kind.hpp, seed 001
// section 9.2). A comparison stores curve 0 (the best foot per speed), curves 1..n (each foot's
// best point per speed) and a summary curve with one ComparedFootRecord per foot. The per-speed
// members sit beside the walker point's own (walker_point_record.hpp).

#include "cyclopt/records/json_fields.hpp"
#include "cyclopt/records/point_record.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace cyclopt::records {

// One speed of a foot's curve, or of curve 0 (the best foot's point there).
struct ComparedSpeedRecord {
  std::string foot;                     // empty on curve 0 where no foot reached the speed
  std::optional<std::string> found_by;  // which sweep step found the point (studies::describe)
  std::optional<std::string> reason;    // why there is none
  double f_mech = kUnset;               // eq. (5.102); NaN: no point
  double sweep_seconds = kUnset;        // wall time of the foot's sweep
  double saving = kUnset;               // curve 0: 1 - f_mech / reference_f_mech
  double reference_f_mech = kUnset;     // curve 0: the reference foot's f_mech at this speed
  // With several seeds: (max - min) / min of f_mech over the seeds' own searches (NaN: a search
  // has no point here, or one seed).
  double seed_spread = kUnset;
  bool operator==(const ComparedSpeedRecord&) const = default;
};

// The summary of one compared foot (the point's parameter is its curve index).
struct ComparedFootRecord {
  std::string foot;
  bool reference = false, best_fitted = false;
  double mean_f_mech = kUnset;  // over the speeds it shares with the reference (NaN: none)
  double saving = kUnset;       // 1 - mean_f_mech / the reference's over those speeds
  int common_speeds = 0, speeds_found = 0, speeds = 0, curves = 0;
  double sweep_seconds = kUnset;
  nlohmann::json foot_spec;  // the foot as foot.schema.json describes it (design data)
  // The reference's record only: the envelope of the best feet against it.
  std::optional<double> envelope_saving;
  std::optional<int> envelope_common_speeds;
  std::optional<double> comparison_seconds;
  // With several seeds (studies/foot_comparison.hpp): the saving of each seed's own searches, the
  // rank by saving (0: best; the reference has none) and whether the foot beat the next-ranked one
  // with every seed (absent for the last, the reference, a single seed).
  std::vector<double> seed_savings;
  std::optional<int> rank;
  std::optional<bool> order_held;
  bool operator==(const ComparedFootRecord&) const = default;
};

// Whether a point's values are a ComparedFootRecord (the summary curve) rather than a speed.
bool is_compared_foot(const nlohmann::json& values);

// Absent members (NaN, nullopt, an empty foot) are not written.
void to_json(nlohmann::json& j, const ComparedSpeedRecord& s);
void from_json(const nlohmann::json& j, ComparedSpeedRecord& s);  // throws RecordError naming the field
void to_json(nlohmann::json& j, const ComparedFootRecord& f);
void from_json(const nlohmann::json& j, ComparedFootRecord& f);

template <>
inline constexpr bool is_point_values<ComparedSpeedRecord> = true;
template <>
inline constexpr bool is_point_values<ComparedFootRecord> = true;

}  // namespace cyclopt::records
