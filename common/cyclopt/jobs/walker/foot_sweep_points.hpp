#pragma once
// A foot's speed sweep (studies::FootSweepSummary) as stored points, shared by the kinds that
// sweep several feet (foot/foot_comparison_kind.cpp, foot/foot_design_kind.cpp): its best point
// per grid speed, a walker point with a records::ComparedSpeedRecord beside it, or a "not found"
// row with the sweep's reason.
#include "cyclopt/continuation/parametric_problem.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"
#include "cyclopt/records/foot_comparison_records.hpp"
#include "cyclopt/studies/foot_comparison.hpp"

#include <vector>

namespace cyclopt::jobs {

struct ComparedSpeedPoint {
  WalkerPoint point;  // no gait where the sweep found none
  records::ComparedSpeedRecord speed;
  storage::SolutionPoint stored() const { return point.stored(speed); }
};

// family: the swept walker's family over the speed (studies::walker_family); point i is {curve, i}.
std::vector<ComparedSpeedPoint> best_points(const continuation::ParametricProblem& family,
                                            const studies::FootSweepSummary& sweep, int curve);

}  // namespace cyclopt::jobs
