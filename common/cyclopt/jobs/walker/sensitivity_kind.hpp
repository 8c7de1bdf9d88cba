#pragma once
// The walker job kind "sensitivity" (issue 15 item 6; seed 001 section 10.1, Fig. 10.1): an
// optimal gait at one speed (from the automatic or a stored start, like optimise), stored with
// its KKT sensitivities (optimum_sensitivities.hpp), then per parameter the +-relative_range
// continuation of studies/sensitivity.hpp from that optimum, its points stored, and one summary
// (records::SensitivitySummaryRecord) comparing the KKT linear prediction with it. Fields beside
// the walker ones of optimise (walker_job_spec.hpp):
//   "parameters": model parameter names (default: every parameter kkt_sensitivity covers whose
//                 value is not 0), "relative_range": in (0, 1) (default 0.1 = +-10 %),
//   "steps": continuation values per direction, [1, 50] (default 5).
//
// The verdict per parameter: "continuation stopped: <message>" when a direction did not reach
// the range; else "kink: <reasons>" when the KKT point flags a kink at p (weakly active rows), the
// predicted active-set change on a side is nearer than the range (the linear prediction holds
// only up to there), the continuation jumped to another curve, or the one-sided difference
// quotients at its smallest step h = range / steps do not bracket the KKT derivative; else
// "agrees". Bracketing, in units of the relative sensitivity s = p / f* df*/dp: for a smooth
// f*(p), q(+h) and q(-h) differ from df*/dp by the curvature term +-f'' h p / 2, on opposite sides,
// so s must lie in [min(s-, s+), max(s-, s+)] widened by kQuotientTolerance.

#include "cyclopt/service/job_kind.hpp"

namespace cyclopt::jobs {

// The widening of the bracket: 2 % of |s| plus 1e-4 (absolute, relative sensitivity units).
inline constexpr double kQuotientRelativeTolerance = 0.02, kQuotientAbsoluteTolerance = 1e-4;

service::JobKind walker_sensitivity_kind();

}  // namespace cyclopt::jobs
