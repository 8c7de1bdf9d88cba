#include "cyclopt/jobs/walker/foot_sweep_points.hpp"

namespace cyclopt::jobs {

std::vector<ComparedSpeedPoint> best_points(const continuation::ParametricProblem& family,
                                            const studies::FootSweepSummary& sweep, int curve) {
  std::vector<ComparedSpeedPoint> points;
  for (std::size_t i = 0; i < sweep.best.size(); ++i) {
    const studies::BestPoint& b = sweep.best[i];
    const storage::PointKey key{curve, static_cast<int>(i)};
    ComparedSpeedPoint p;
    p.speed.foot = sweep.name;
    if (b.found) {
      p.point = walker_point(family, b.point, key);
      p.speed.found_by = studies::describe(b);
    } else {
      p.point.row.key = key;
      p.point.row.parameter = b.speed;
      p.point.row.status = "not found";
      p.speed.reason = b.reason;
    }
    p.speed.f_mech = sweep.f_mech[i];
    p.speed.sweep_seconds = sweep.seconds;
    points.push_back(std::move(p));
  }
  return points;
}

}  // namespace cyclopt::jobs
