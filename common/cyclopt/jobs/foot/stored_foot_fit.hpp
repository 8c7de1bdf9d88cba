#pragma once
// A walker job's foot may name the fit a foot_fit job stored (foot_fit_kind.hpp, issue 20 item 3)
// instead of giving a preset or the foot's parameters, and so may each of a foot_comparison's
// "feet" and its "reference" (the reference's form: service/stored_references.hpp). The server replaces the
// reference by the fitted foot spec (records::FootFitRecord::foot, named "fitted HMT (job 7)")
// when the job is submitted, as it does for a stored "start" (walker/stored_start.hpp); the job stores
// the spec as submitted and its resolved spec with the foot's parameters. A reference to a job
// that does not exist, is not a foot_fit job, has not finished, or whose fit of that model is
// missing or did not converge is rejected naming foot.fit.job or foot.fit.model.

#include "cyclopt/storage_read/result_reader.hpp"

#include <nlohmann/json.hpp>

namespace cyclopt::jobs {

// `spec` with every stored-fit foot replaced by the fitted foot spec. Throws SpecError.
nlohmann::json with_stored_foot_fit(nlohmann::json spec, storage::ResultReader& store);

}  // namespace cyclopt::jobs
