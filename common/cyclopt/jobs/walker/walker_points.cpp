#include "cyclopt/jobs/walker/walker_points.hpp"

#include "cyclopt/records/walker_point_record.hpp"
#include "cyclopt/jobs/walker/walker_records.hpp"
#include "cyclopt/walker/gait_problem.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

namespace cyclopt::jobs {

namespace {

// The point of `gait` with `values` (whose gait it sets) as its values.
storage::SolutionPoint stored_point(const walker::PeriodicGait<double>& gait, records::WalkerPointRecord values,
                                    storage::PointKey key, double parameter) {
  storage::SolutionPoint p;
  p.key = key;
  p.parameter = parameter;
  values.gait = gait_record(gait);
  if (gait.real) {
    if (const auto t = trajectory_record(gait.trajectory)) p.trajectory = nlohmann::json(*t);
    p.objective = gait.objective;
    p.constraint_violation = std::max({0.0, std::abs(gait.speed_equality), gait.inequalities.maxCoeff()});
  }
  p.status = gait.real ? "ok" : "no real solution";
  p.values = values;
  return p;
}

records::WalkerPointRecord optimum_values(const walker::GaitOptimum& opt) {
  records::WalkerPointRecord v;
  v.solver = solver_record(opt.summary);
  v.start = opt.start;
  v.start_objective = opt.start_objective;
  v.x.assign(opt.z.data(), opt.z.data() + opt.z.size());  // a later job can start from it (stored_start.hpp)
  return v;
}

storage::SolutionPoint optimum_point(const walker::GaitOptimum& opt, const records::WalkerPointRecord& values,
                                     storage::PointKey key, double parameter) {
  storage::SolutionPoint p = stored_point(opt.gait, values, key, parameter);
  p.iterations = opt.summary.iterations;
  p.status = nlp::to_string(opt.summary.termination);
  return p;
}

}  // namespace

storage::SolutionPoint point_of(const walker::PeriodicGait<double>& gait, const walker::GaitStart& start,
                                storage::PointKey key, double parameter) {
  records::WalkerPointRecord v;
  v.start = start.origin;
  v.x.assign(start.x.data(), start.x.data() + start.x.size());
  return stored_point(gait, v, key, parameter);
}

storage::SolutionPoint point_of(const walker::GaitOptimum& opt, storage::PointKey key, double parameter,
                                std::optional<records::KktSensitivitiesRecord> sensitivities) {
  records::WalkerPointRecord v = optimum_values(opt);
  v.sensitivities = std::move(sensitivities);
  return optimum_point(opt, v, key, parameter);
}

storage::SolutionPoint point_of(const continuation::ParametricProblem& family, const continuation::CurvePoint& c,
                                storage::PointKey key) {
  const std::unique_ptr<nlp::Problem> problem = family.at(c.parameter);
  walker::GaitOptimum opt;
  opt.summary = c.corrector;
  opt.z = c.x;
  opt.gait = dynamic_cast<const walker::GaitProblem&>(*problem).gait_at(c.x);
  opt.start = c.predictor_attempts > 0 ? "QP predictor" : "previous point";
  records::WalkerPointRecord v = optimum_values(opt);
  v.continuation = records::ContinuationStepRecord{.curve_id = c.curve_id,
                                                   .on_grid = c.on_grid,
                                                   .converged = c.converged,
                                                   .predictor_attempts = c.predictor_attempts,
                                                   .predictor_steps = c.predictor_steps,
                                                   .kappa = c.kappa,
                                                   .trust_region = c.trust_region,
                                                   .point_seconds = c.seconds};
  return optimum_point(opt, v, key, c.parameter);
}

}  // namespace cyclopt::jobs
