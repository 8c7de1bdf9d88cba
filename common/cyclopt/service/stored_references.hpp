#pragma once
// A spec may name results this server stored instead of giving their values:
//
//   "start": {"job": 7, "point": 3}               a walker job's start: job 7's point 3 of curve 0
//   "start": {"job": 7, "curve": 2, "point": 11}  ... the stored point (curve 2, point 11)
//   "foot": {"fit": {"job": 7}}                   a foot: job 7's HMT fit (point 1)
//   "foot": {"fit": {"job": 7, "model": "HM"}}    ... its HM fit (point 0)
//
// (a foot of "foot", "reference" or "feet[i]"; "curve" and "point" as `cyclopt query JOB` shows
// them). Their form is part of the spec language and is checked here, where a client without
// the database can check it too; the server replaces them by what is stored when the job is
// submitted (jobs/walker/stored_start.hpp, jobs/foot/stored_foot_fit.hpp), and the job keeps the
// spec as submitted and its resolved spec with the values (resolved_spec.hpp).

#include "cyclopt/storage_read/job_record.hpp"
#include "cyclopt/storage_read/solution_point.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cyclopt::service {

struct StoredPointReference {
  std::int64_t job_id = 0;
  storage::PointKey key;
  bool curve_given = false;  // "curve" was written (errors about the point then name start.curve)
};

struct StoredFitReference {
  nlohmann::json::json_pointer where;  // of the foot in the spec
  std::string path;                    // its field: "foot", "reference", "feet[2]"
  std::int64_t job_id = 0;
  std::string model;                   // "HM" | "HMT" (default)
};

// The spec's "start" when it names a stored point, else nullopt. Throws SpecError (start.job,
// start.curve, start.point) when the reference is malformed.
std::optional<StoredPointReference> stored_point_reference(const nlohmann::json& spec);

// Every foot of `spec` that names a stored fit, in the spec's order. Throws SpecError (e.g.
// feet[1].fit.model) when one is malformed.
std::vector<StoredFitReference> stored_fit_references(const nlohmann::json& spec);

// `spec` without a stored-point "start" once the reference is well-formed (throws SpecError if
// not): what a client without the database can check of the rest of the spec.
nlohmann::json without_stored_start(nlohmann::json spec);

// The text a stored job is run from where the database is not at hand (a resumed job, a
// cyclopt-worker): its spec as submitted, or, when it names stored results, its resolved spec,
// which holds their values.
std::string runnable_spec_text(const storage::JobRecord& job);

}  // namespace cyclopt::service
