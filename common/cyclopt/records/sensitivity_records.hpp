#pragma once
// The sensitivity family of the result contract (issue 15 item 6; seed 001 section 10.1): the
// derivatives of the optimal objective with respect to the model parameters from the Lagrangian
// at the KKT point (studies/kkt_sensitivity.hpp), stored with an optimum as values.sensitivities
// (walker optimise and sensitivity jobs, every foot_design density's design), and what a
// sensitivity job stores per parameter: the +-range continuation's points (studies/sensitivity.hpp)
// and a summary comparing the two.

#include "cyclopt/records/json_fields.hpp"
#include "cyclopt/records/point_record.hpp"

#include <nlohmann/json.hpp>

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace cyclopt::records {

// Curves of a sensitivity job: the optimum (point 0), one summary per parameter (point k for the
// k-th parameter), the continuation of the k-th parameter.
inline constexpr int kSensitivityOptimumCurve = 0, kSensitivitySummaryCurve = 1;
inline int sensitivity_continuation_curve(int parameter_index) { return 2 + parameter_index; }

// Where the linearised optimum changes its active set when the parameter moves one way.
struct ActiveSetChangeRecord {
  double relative_change = std::numeric_limits<double>::infinity();  // |p - p0| / |p0|; inf (stored null): none predicted
  std::string constraint;  // the row or bound that enters or leaves; empty: none
  bool enters = false;     // true: becomes active; false: its multiplier reaches 0
  bool operator==(const ActiveSetChangeRecord&) const = default;
};

// One parameter's KKT sensitivity.
struct ParameterSensitivityRecord {
  std::string name;
  double value = kUnset;       // the parameter at the optimum
  double derivative = kUnset;  // d f*/d p per unit of p
  double relative = kUnset;    // p / f* d f*/d p
  bool kink = false;           // the active set changes at p itself (one side): f* has a kink there
  ActiveSetChangeRecord decrease, increase;
  std::vector<std::string> weakly_active;  // the rows behind a kink
  bool operator==(const ParameterSensitivityRecord&) const = default;
};

// values.sensitivities of an optimum: the numbers, or (unavailable) why there are none.
struct KktSensitivitiesRecord {
  std::optional<std::string> unavailable;  // set: no numbers (the multipliers were unusable, or the evaluation failed)
  std::string multipliers;                 // where the multipliers came from
  double objective = kUnset;               // f* at the point the multipliers belong to
  double lagrangian_gradient = kUnset;     // |grad_z L|_inf with them
  int active_constraints = 0;
  bool unique_multipliers = true;          // false: dependent active gradients (one multiplier set of several)
  std::vector<std::string> weakly_active;
  std::vector<ParameterSensitivityRecord> parameters;
  double seconds = kUnset;
  bool operator==(const KktSensitivitiesRecord&) const = default;
};

// A point of a sensitivity job's continuation curve (the point's parameter is relative_change).
struct SensitivityStepRecord {
  std::string parameter;
  double value = kUnset;            // p
  double relative_change = kUnset;  // (p - p0) / p0
  double delta_objective = kUnset;  // f*(p) - f*(p0) along the followed curve
  int curve_id = 0;                 // 0: the optimum's curve; others after a jump
  bool operator==(const SensitivityStepRecord&) const = default;
};

// A sensitivity job's comparison for one parameter: the KKT linear prediction of Delta f at
// -range and +range against the continuation's Delta f there (or at the furthest value it
// reached: reached_* then is less than the range), and the verdict.
struct SensitivitySummaryRecord {
  std::string parameter;
  double value = kUnset, derivative = kUnset, relative = kUnset;  // from the KKT sensitivity
  bool kink = false;                                              // the KKT kink flag
  double relative_range = kUnset;
  double predicted_decrease = kUnset, predicted_increase = kUnset;        // derivative * value * (-+range)
  double continuation_decrease = kUnset, continuation_increase = kUnset;  // Delta f at the furthest value reached
  double reached_decrease = kUnset, reached_increase = kUnset;            // its relative change (signed)
  double quotient_decrease = kUnset, quotient_increase = kUnset;          // one-sided difference quotients at the smallest step
  int jumps = 0;
  std::string verdict;  // "agrees", "kink: <reason>" or "continuation stopped: <message>"
  bool operator==(const SensitivitySummaryRecord&) const = default;
};

// Whether a point's values are a SensitivitySummaryRecord (or a SensitivityStepRecord).
bool is_sensitivity_summary(const nlohmann::json& values);
bool is_sensitivity_step(const nlohmann::json& values);

void to_json(nlohmann::json& j, const ActiveSetChangeRecord& c);
void from_json(const nlohmann::json& j, ActiveSetChangeRecord& c);  // throws RecordError naming the field
void to_json(nlohmann::json& j, const ParameterSensitivityRecord& p);
void from_json(const nlohmann::json& j, ParameterSensitivityRecord& p);
void to_json(nlohmann::json& j, const KktSensitivitiesRecord& k);
void from_json(const nlohmann::json& j, KktSensitivitiesRecord& k);
void to_json(nlohmann::json& j, const SensitivityStepRecord& s);
void from_json(const nlohmann::json& j, SensitivityStepRecord& s);
void to_json(nlohmann::json& j, const SensitivitySummaryRecord& s);
void from_json(const nlohmann::json& j, SensitivitySummaryRecord& s);

template <>
inline constexpr bool is_point_values<SensitivityStepRecord> = true;
template <>
inline constexpr bool is_point_values<SensitivitySummaryRecord> = true;

}  // namespace cyclopt::records
