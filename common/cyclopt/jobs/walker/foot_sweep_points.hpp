#pragma once
// A foot's speed sweep (studies::FootSweepSummary) as stored points, shared by the kinds that
// sweep several feet (foot_comparison_kind.hpp, foot_design_kind.hpp): its best point per grid
// speed with a records::ComparedSpeedRecord beside the walker point's own, or a "not found" row
// with the sweep's reason.
#include "cyclopt/continuation/parametric_problem.hpp"
#include "cyclopt/storage/solution_point.hpp"
#include "cyclopt/studies/foot_comparison.hpp"

#include <vector>

namespace cyclopt::jobs {

// family: the swept walker's family over the speed (studies::walker_family); point i is {curve, i}.
std::vector<storage::SolutionPoint> best_points(const continuation::ParametricProblem& family,
                                                const studies::FootSweepSummary& sweep, int curve);

}  // namespace cyclopt::jobs
