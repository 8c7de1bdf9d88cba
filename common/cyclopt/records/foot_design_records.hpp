#pragma once
// The foot_design family of the result contract (service/foot_design_kind.hpp, seed 001 section
// 10.2). A design job stores curve 0 with one DesignedFootRecord per density, the reference
// sweeps (curves 1, 2: records::ComparedSpeedRecord beside the walker point's own), and per
// density k the design multistart's optima (curve 3 + 4k) and the free-foot continuation's points
// (curve 4 + 4k), each with a DesignPointRecord (its foot as "design_foot") beside the walker
// point's own, and the fixed-foot sweeps of the high- and low-speed designs (curves 5 + 4k and
// 6 + 4k: ComparedSpeedRecord).

#include "cyclopt/records/json_fields.hpp"
#include "cyclopt/records/point_record.hpp"
#include "cyclopt/records/sensitivity_records.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace cyclopt::records {

// Curves of a foot_design job.
inline constexpr int kDesignCurve = 0, kStartFootCurve = 1, kPointFeetCurve = 2;
inline int design_multistart_curve(int density_index) { return 3 + 4 * density_index; }
inline int free_foot_curve(int density_index) { return 4 + 4 * density_index; }
inline int high_design_curve(int density_index) { return 5 + 4 * density_index; }
inline int low_design_curve(int density_index) { return 6 + 4 * density_index; }

// A designed foot: its parameters with the quantities that follow them at the density (E.3-E.7).
struct DesignedFoot {
  std::map<std::string, double> parameters;  // by the foot model's names (foot.schema.json)
  double m_F = kUnset, r_F = kUnset, J_F = kUnset, theta_F0 = kUnset;  // kg, m, kg m^2, rad
  bool operator==(const DesignedFoot&) const = default;
};

// One point of a design multistart (an optimum, kept whatever its class) or of the free-foot
// continuation (class members absent).
struct DesignPointRecord {
  double density = kUnset;                  // kg/m^2
  DesignedFoot foot;
  std::vector<std::string> active_bounds;   // rows of (10.1) at their bound (multistart optima)
  std::optional<std::string> design_class;  // admissible | stilt | wheel | no rolling (design_class.hpp)
  std::optional<std::string> class_reason;  // the rule and the measured values
  std::vector<int> reached_by_starts;       // multistart runs that reached the optimum
  bool design = false;                      // the density's design (the best admissible optimum)
  bool operator==(const DesignPointRecord&) const = default;
};

// The result of one density (curve 0; the point's parameter is the density).
struct DesignedFootRecord {
  double density = kUnset;
  bool admissible = false;             // an admissible design was found (else reason says why not)
  std::optional<std::string> reason;
  int starts = 0, kkt_starts = 0;      // design multistart runs, runs that reached a KKT point
  int admissible_optima = 0, stilt_optima = 0, wheel_optima = 0, no_rolling_optima = 0;
  int under_resolved_optima = 0;       // (records stored before the class existed read as 0)
  int best = -1;                       // point index of the design on its multistart curve
  double design_objective = kUnset;    // at the design speed
  DesignedFoot design;                 // the foot optimal at the design speed (when admissible)
  std::vector<std::string> active_bounds;
  int speeds = 0;                      // of the grid
  int free_foot_speeds = 0;            // grid speeds the free-foot continuation reached
  double low_speed = kUnset;           // the lowest speed it reached
  DesignedFoot low_speed_design;       // the foot optimal there
  // The fixed-foot sweep of the design: mean f_mech over the speeds it reached, savings against
  // the start foot and point feet over the speeds both reach (NaN without references).
  int speeds_reached = 0;
  double mean_f_mech = kUnset, saving_vs_start = kUnset, saving_vs_point = kUnset;
  // The same for the low-speed design.
  int low_speeds_reached = 0;
  double low_mean_f_mech = kUnset, low_saving_vs_start = kUnset, low_saving_vs_point = kUnset;
  // The density's answer, the better of the two (studies::better_design): "design" or "low-speed
  // design" (records stored before it existed read as "design").
  std::string answer = "design";
  double multistart_seconds = kUnset, continuation_seconds = kUnset, sweep_seconds = kUnset, seconds = kUnset;
  // The KKT sensitivities of the design's optimum (foot parameters free, so their own derivatives
  // are those of the design bounds); absent when its solve did not converge.
  std::optional<KktSensitivitiesRecord> sensitivities;
  bool operator==(const DesignedFootRecord&) const = default;
};

// Whether a point's values are a DesignedFootRecord (curve 0 of a foot_design job).
bool is_designed_foot(const nlohmann::json& values);

void to_json(nlohmann::json& j, const DesignedFoot& f);
void from_json(const nlohmann::json& j, DesignedFoot& f);  // throws RecordError naming the field
void to_json(nlohmann::json& j, const DesignPointRecord& p);
void from_json(const nlohmann::json& j, DesignPointRecord& p);
void to_json(nlohmann::json& j, const DesignedFootRecord& d);
void from_json(const nlohmann::json& j, DesignedFootRecord& d);

template <>
inline constexpr bool is_point_values<DesignPointRecord> = true;
template <>
inline constexpr bool is_point_values<DesignedFootRecord> = true;

}  // namespace cyclopt::records
