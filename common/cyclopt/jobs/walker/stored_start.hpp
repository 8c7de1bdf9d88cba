#pragma once
// A walker job's "start" may name a point a job stored instead of listing the gait parameters x,
// so that a user re-runs or refines what an earlier job found (issue 17 item 7):
//
//   "start": {"job": 7, "point": 3}               job 7's point 3 of curve 0
//   "start": {"job": 7, "curve": 2, "point": 11}  the stored point (curve 2, point 11)
//
// (the "curve" and "point" of `cyclopt query JOB`). The server replaces the reference by the
// point's x (values.x, the first (M - 1) n_b numbers: the gait, without free model parameters the
// stored job optimised) when the job is submitted; the job then stores the spec as submitted and
// its resolved spec with that x (resolved_spec.hpp). A reference to a job or point that does not
// exist, a point without x, or a job of another scene, foot model or Bezier degree is rejected
// naming start.job, start.curve or start.point.

#include "cyclopt/storage/job_record.hpp"
#include "cyclopt/storage/result_store.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace cyclopt::jobs {

// `spec` with a stored-point "start" replaced by the point's x; any other spec unchanged. Throws
// SpecError.
nlohmann::json with_stored_start(nlohmann::json spec, storage::ResultStore& store);

// `spec` without a stored-point "start" once the reference is well-formed (throws SpecError if
// not): what a client without the database can check of the rest of the spec.
nlohmann::json without_stored_start(nlohmann::json spec);

// The text a stored job is run from where the database is not at hand (a resumed job, a
// cyclopt-worker): its spec as submitted, or, when its start names a stored point or a foot a
// stored fit (stored_foot_fit.hpp), its resolved spec, where they are the point's x and the foot.
std::string runnable_spec_text(const storage::JobRecord& job);

}  // namespace cyclopt::jobs
