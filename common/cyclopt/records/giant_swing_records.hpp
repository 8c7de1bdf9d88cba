#pragma once
// The giant-swing family of the result contract (seed 000 ch. 3-5): what a giant_swing job stores
// as its one point's values, in the units of the seed's tables (phi'/omega, deg, deg/s, J,
// rad^2/s^5, Nm^2 s): the motion simulated in the full model round by round, and what the method
// found - the seed's piecewise-linear hip torque (part A) or the Bezier minimum-jerk swing (part B).

#include "cyclopt/records/json_fields.hpp"
#include "cyclopt/records/point_record.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace cyclopt::records {

// One completed round (seed 000 eq. 4.11-4.13 per round).
struct SwingRoundRecord {
  double phi_rate_over_omega = kUnset;  // phi' / omega at the round's end
  double alpha_deg = kUnset, alpha_rate_deg_s = kUnset;
  double duration_s = kUnset, friction_loss_J = kUnset, jerk_rad2_s5 = kUnset, moment_Nm2_s = kUnset;
  bool operator==(const SwingRoundRecord&) const = default;
};

// A stage of the seed's multistage Nelder-Mead.
struct SeedStageRecord {
  int support_points = 0;
  double step_Nm = kUnset;  // lambda
  double score = kUnset;    // best score after the stage
  int evaluations = 0;      // model integrations in it
  bool operator==(const SeedStageRecord&) const = default;
};

// The seed's method (part A): piecewise-linear M_alpha(phi), evaluation functions 4.9/4.10/4.14.
struct SeedMethodRecord {
  double score = kUnset;
  std::vector<double> support_values_Nm;  // M_alpha at the support points
  bool failed = false;                    // the best torque's swing left the admissible ranges
  std::vector<SeedStageRecord> stages;
  int model_integrations = 0;
  bool budget_exhausted = false;
  bool operator==(const SeedMethodRecord&) const = default;
};

// Part B: alpha = b(phi) with minimum jerk on the reduced model, Ipopt.
struct MinimumJerkRecord {
  std::vector<double> coefficients_rad;  // the free Bezier coefficients
  int free_coefficients = 0;
  double jerk_rad2_s5 = kUnset, start_jerk_rad2_s5 = kUnset;  // reduced model, eq. 4.12
  double phi_rate_over_omega_minus_1 = kUnset;                  // the boundary equality's error
  double friction_loss_J = kUnset, moment_Nm2_s = kUnset;
  std::string solver, termination, message;  // the NLP solve
  bool success = false;
  int iterations = 0;
  std::vector<double> floquet_multiplier_moduli;  // periodic motions: of the one-step map at the handstand
  bool operator==(const MinimumJerkRecord&) const = default;
};

struct GiantSwingRecord {
  std::string motion;   // single | periodic | accelerating | decelerating
  std::string method;   // seed | bezier
  nlohmann::json task;  // the task with its options (giant_swing_task.schema.json)
  std::vector<SwingRoundRecord> rounds;  // in the full model
  int rounds_completed = 0;
  std::optional<std::string> failure_reason;  // the swing left the admissible ranges
  std::optional<double> failure_phi_deg;      // where
  int integrations = 0;
  double wall_seconds = kUnset;
  std::optional<SeedMethodRecord> seed;     // method seed
  std::optional<MinimumJerkRecord> bezier;  // method bezier
  bool operator==(const GiantSwingRecord&) const = default;
};

void to_json(nlohmann::json& j, const SwingRoundRecord& r);
void from_json(const nlohmann::json& j, SwingRoundRecord& r);  // throws RecordError naming the field
// The seed's and the Bezier method's members stand beside the others in one object.
void to_json(nlohmann::json& j, const GiantSwingRecord& g);
void from_json(const nlohmann::json& j, GiantSwingRecord& g);

template <>
inline constexpr bool is_point_values<GiantSwingRecord> = true;

}  // namespace cyclopt::records
