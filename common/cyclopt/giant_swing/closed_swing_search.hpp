#pragma once
// Minimum jerk over closed swings without an NLP solver (until the Ipopt adapter takes the
// MinimumJerkProblem directly): Nelder-Mead over the direction d of the free Bezier coefficients,
// each trial scaled onto the boundary equality by scale_to_close (Newton with the exact
// derivative), so every trial is a closed swing (phi'(2 pi) = omega, alpha = alpha' = 0 exactly);
// trials outside the bounds or the phi' > 0 constraint score +infinity.

#include "cyclopt/giant_swing/minimum_jerk_problem.hpp"
#include "cyclopt/nlp/nelder_mead.hpp"

namespace cyclopt::giant_swing {

struct ClosedSwingSearchResult {
  bool ok = false;
  Eigen::VectorXd coefficients;  // free Bezier coefficients c3..c6 of the best closed swing
  double jerk = 0.0;
  nlp::NelderMeadSummary search;
  int integrations = 0;          // zero-dynamics integrations (problem.integrations())
};

ClosedSwingSearchResult minimise_jerk_over_closed_swings(MinimumJerkProblem& problem, const Eigen::VectorXd& start_shape,
                                                         const nlp::NelderMeadOptions& options);

}  // namespace cyclopt::giant_swing
