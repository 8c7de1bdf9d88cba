#include "cyclopt/service/walker_points.hpp"

#include "cyclopt/io/gait_json.hpp"
#include "cyclopt/walker/gait_problem.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

namespace cyclopt::service {

storage::SolutionPoint point_of(const walker::PeriodicGait<double>& gait, storage::PointKey key, double parameter) {
  storage::SolutionPoint p;
  p.key = key;
  p.parameter = parameter;
  nlohmann::json g = io::gait_to_json(gait, true);
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
  p.values["solver"] = io::summary_to_json(opt.summary);
  p.values["start"] = opt.start;
  p.values["start_objective"] = opt.start_objective;
  return p;
}

storage::SolutionPoint point_of(const continuation::ParametricProblem& family, const continuation::CurvePoint& c,
                                storage::PointKey key) {
  const std::unique_ptr<nlp::Problem> problem = family.at(c.parameter);
  walker::GaitOptimum opt;
  opt.summary = c.corrector;
  opt.z = c.x;
  opt.gait = dynamic_cast<const walker::GaitProblem&>(*problem).gait_at(c.x);
  opt.start = c.predictor_attempts > 0 ? "QP predictor" : "previous point";
  storage::SolutionPoint p = point_of(opt, key, c.parameter);
  p.values["curve_id"] = c.curve_id;
  p.values["on_grid"] = c.on_grid;
  p.values["converged"] = c.converged;
  p.values["predictor_attempts"] = c.predictor_attempts;
  p.values["predictor_steps"] = c.predictor_steps;
  if (std::isfinite(c.kappa)) p.values["kappa"] = c.kappa;
  p.values["trust_region"] = c.trust_region;
  p.values["point_seconds"] = c.seconds;
  p.values["x"] = std::vector<double>(c.x.data(), c.x.data() + c.x.size());
  return p;
}

}  // namespace cyclopt::service
