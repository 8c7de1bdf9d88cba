#pragma once
// The foot_fit family of the result contract (service/foot_fit_kind.hpp, seed 001 section 4.2):
// a foot_fit job stores one FootFitRecord per fitted model, point 0 the HM fit (eq. 4.16) and
// point 1 the HMT fit (eq. 4.21) of curve 0. `cyclopt-foot fit --json` prints the same record,
// and a walker job's "foot": {"fit": {"job": J, "model": "HMT"}} reads its foot_spec
// (service/stored_foot_fit.hpp).

#include "cyclopt/records/json_fields.hpp"
#include "cyclopt/records/point_record.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace cyclopt::records {

// One shape parameter with its box (4.13 / 4.18); NaN standard error: held on a bound or fixed.
// The spreads over strides and stance boundaries (foot_fit/fit_spread.hpp) are null where not
// estimated (and absent in records stored before them); `flag` says why the parameter is not
// well determined, empty when nothing is wrong.
struct FittedParameterRecord {
  std::string name, unit;
  double value = kUnset, lower = kUnset, upper = kUnset;  // infinite bounds are stored as null
  double standard_error = kUnset;
  bool fixed = false, at_bound = false;
  double stride_spread = kUnset, boundary_spread = kUnset;
  std::string flag;
  bool operator==(const FittedParameterRecord&) const = default;
};

struct FittedTrialRecord {
  std::string source;
  int samples = 0;
  double rms = kUnset, max = kUnset;  // m
  double x_off = kUnset;              // m, the trial's offset (4.15)
  bool operator==(const FittedTrialRecord&) const = default;
};

struct ConvexityRowRecord {
  std::string condition;  // a row of (3.21) / (3.24), or the HMT toe margin
  double value = kUnset;  // >= 0 where convex
  bool operator==(const ConvexityRowRecord&) const = default;
};

struct FootFitRecord {
  std::string model;  // "HM" or "HMT"
  bool converged = false;
  std::string message;
  int iterations = 0;
  double seconds = kUnset;
  int samples = 0, unknowns = 0;
  double rms = kUnset, max_residual = kUnset, noise_estimate = kUnset;  // m
  std::vector<FittedParameterRecord> parameters;
  std::vector<FittedTrialRecord> trials;
  bool convex = false;
  std::vector<ConvexityRowRecord> convexity;
  nlohmann::json foot;  // the fitted foot as foot.schema.json describes it
  // The refits behind the spreads: counted, of them not converged, boundary tolerance (s);
  // 0, 0, null where no spread was estimated.
  int spread_refits = 0, spread_unconverged = 0;
  double boundary_tolerance = kUnset;
  bool operator==(const FootFitRecord&) const = default;
};

// The fitted foot angles theta_F,k,j (rad) per trial k and sample j, unknowns of (4.16) / (4.21):
// stored as the fit point's trajectory, they give the model ankle of every sample for Fig. 4.3a.
struct FootFitAnglesRecord {
  std::vector<std::vector<double>> theta;
  bool operator==(const FootFitAnglesRecord&) const = default;
};

// Whether a point's values are a FootFitRecord.
bool is_foot_fit(const nlohmann::json& values);

void to_json(nlohmann::json& j, const FootFitRecord& f);
void from_json(const nlohmann::json& j, FootFitRecord& f);  // throws RecordError naming the field
void to_json(nlohmann::json& j, const FootFitAnglesRecord& a);
void from_json(const nlohmann::json& j, FootFitAnglesRecord& a);  // throws RecordError naming the element

template <>
inline constexpr bool is_point_values<FootFitRecord> = true;
template <>
inline constexpr bool is_point_trajectory<FootFitAnglesRecord> = true;

}  // namespace cyclopt::records
