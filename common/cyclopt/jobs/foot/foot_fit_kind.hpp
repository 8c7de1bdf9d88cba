#pragma once
// Built-in job kind "foot_fit" (scene walker): the seed's three steps of fitting a rolling foot
// to measured ankle trajectories (seed 001 section 4.2: circle-fit start 4.9-4.12, HM fit
// 4.13-4.17, HMT fit 4.18-4.22 from it), as `cyclopt-foot fit` runs them.
//
//   {"scene": "walker", "task": "foot_fit",
//    "trials": [{"source": "trial1.trc", "x": [m, ...], "z": [m, ...]}, ...],
//    "toe_bound": true | false (default true: the seed's l_MT <= z_min, eq. 4.18b)}
//
// The trials are the sagittal ankle tracks of the rolling phase inline (io/foot_fit_json.hpp;
// `cyclopt-foot fit --job-spec FILE TRIALS...` and `cyclopt submit --task foot_fit --trials
// A,B,...` read .trc / CSV files, naming file, line and column of a malformed one, and write
// them), so a spec of at most 16 KiB (channels::kMaxSpecBytes) carries about 1000 samples. A
// trial the circle-fit start cannot use is rejected at submission under "trials".
//
// Stored (curve 0): point 0 the HM fit, point 1 the HMT fit, each a records::FootFitRecord
// (parameters with bounds and standard errors, RMS / max residual, residual per trial, convexity
// check, the fitted foot spec); parameter 0 / 1, objective the RMS residual (m), status
// converged or the solver's reason; its trajectory the fitted foot angles per trial and sample
// (records::FootFitAnglesRecord). A walker job uses a stored fit as its foot by reference,
// "foot": {"fit": {"job": J, "model": "HMT"}} (stored_foot_fit.hpp).

#include "cyclopt/service/job_kind.hpp"

namespace cyclopt::jobs {

service::JobKind foot_fit_kind();

}  // namespace cyclopt::jobs
