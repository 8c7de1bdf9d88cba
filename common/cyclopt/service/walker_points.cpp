#include "cyclopt/service/walker_points.hpp"

#include <algorithm>
#include <cmath>

namespace cyclopt::service {

storage::SolutionPoint point_of(const walker::PeriodicGait<double>& gait, storage::PointKey key, double parameter) {
  storage::SolutionPoint p;
  p.key = key;
  p.parameter = parameter;
  nlohmann::json g = walker::gait_to_json(gait, true);
  if (g.contains("trajectory")) {
    p.trajectory = g["trajectory"];
    g.erase("trajectory");
  }
  p.values["gait"] = g;
  if (gait.real) {
    p.objective = gait.objective;
    p.constraint_violation = std::max({0.0, std::abs(gait.speed_equality), gait.inequalities.maxCoeff()});
  }
  p.status = gait.real ? "ok" : "no real solution";
  return p;
}

storage::SolutionPoint point_of(const walker::GaitOptimum& opt, storage::PointKey key, double parameter) {
  storage::SolutionPoint p = point_of(opt.gait, key, parameter);
  p.iterations = opt.summary.iterations;
  p.status = nlp::to_string(opt.summary.termination);
  p.values["solver"] = walker::summary_to_json(opt.summary);
  p.values["start"] = opt.start;
  p.values["start_objective"] = opt.start_objective;
  return p;
}

}  // namespace cyclopt::service
