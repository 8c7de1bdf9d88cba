#include "cyclopt/jobs/walker/foot_sweep_points.hpp"

#include "cyclopt/records/foot_comparison_records.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"

namespace cyclopt::jobs {

std::vector<storage::SolutionPoint> best_points(const continuation::ParametricProblem& family,
                                                const studies::FootSweepSummary& sweep, int curve) {
  std::vector<storage::SolutionPoint> points;
  for (std::size_t i = 0; i < sweep.best.size(); ++i) {
    const studies::BestPoint& b = sweep.best[i];
    const storage::PointKey key{curve, static_cast<int>(i)};
    storage::SolutionPoint p;
    records::ComparedSpeedRecord r;
    r.foot = sweep.name;
    if (b.found) {
      p = point_of(family, b.point, key);
      r.found_by = studies::describe(b);
    } else {
      p.key = key;
      p.parameter = b.speed;
      p.status = "not found";
      r.reason = b.reason;
    }
    r.f_mech = sweep.f_mech[i];
    r.sweep_seconds = sweep.seconds;
    p.values.update(nlohmann::json(r));
    points.push_back(std::move(p));
  }
  return points;
}

}  // namespace cyclopt::jobs
