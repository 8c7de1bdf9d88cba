#pragma once
// A walker job's "start" may name a point a job stored instead of listing the gait parameters x,
// so that a user re-runs or refines what an earlier job found (issue 17 item 7; the reference's
// form: service/stored_references.hpp). The server replaces the reference by the point's x (values.x, the first (M - 1) n_b numbers: the gait, without free model parameters the
// stored job optimised) when the job is submitted; the job then stores the spec as submitted and
// its resolved spec with that x (resolved_spec.hpp). The point may be a gait job's or a
// foot_comparison's (the gait of the foot on the point's curve). A reference to a job or point that does not
// exist, a point without x, or a job of another scene, foot model or Bezier degree is rejected
// naming start.job, start.curve or start.point.

#include "cyclopt/storage_read/result_reader.hpp"

#include <nlohmann/json.hpp>

namespace cyclopt::jobs {

// `spec` with a stored-point "start" replaced by the point's x; any other spec unchanged. Throws
// SpecError.
nlohmann::json with_stored_start(nlohmann::json spec, storage::ResultReader& store);

}  // namespace cyclopt::jobs
