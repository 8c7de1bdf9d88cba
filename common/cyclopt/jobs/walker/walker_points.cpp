#include "cyclopt/jobs/walker/walker_points.hpp"

#include "cyclopt/jobs/walker/walker_records.hpp"
#include "cyclopt/walker/gait_problem.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace cyclopt::jobs {

namespace {

// The point of `gait` with `values` (whose gait it sets) as its values.
WalkerPoint gait_point(const walker::PeriodicGait<double>& gait, records::WalkerPointRecord values, storage::PointKey key,
                       double parameter) {
  WalkerPoint w;
  w.row.key = key;
  w.row.parameter = parameter;
  values.gait = gait_record(gait);
  if (gait.real) {
    w.trajectory = trajectory_record(gait.trajectory);
    w.row.objective = gait.objective;
    w.row.constraint_violation = std::max({0.0, std::abs(gait.speed_equality), gait.inequalities.maxCoeff()});
  }
  w.row.status = gait.real ? "ok" : "no real solution";
  w.values = std::move(values);
  return w;
}

records::WalkerPointRecord optimum_values(const walker::GaitOptimum& opt) {
  records::WalkerPointRecord v;
  v.solver = solver_record(opt.summary);
  v.start = opt.start;
  v.start_objective = opt.start_objective;
  v.x.assign(opt.z.data(), opt.z.data() + opt.z.size());  // a later job can start from it (stored_start.hpp)
  return v;
}

WalkerPoint optimum_point(const walker::GaitOptimum& opt, const records::WalkerPointRecord& values, storage::PointKey key,
                          double parameter) {
  WalkerPoint w = gait_point(opt.gait, values, key, parameter);
  w.row.iterations = opt.summary.iterations;
  w.row.status = nlp::to_string(opt.summary.termination);
  return w;
}

}  // namespace

WalkerPoint walker_point(const walker::PeriodicGait<double>& gait, const walker::GaitStart& start, storage::PointKey key,
                         double parameter) {
  records::WalkerPointRecord v;
  v.start = start.origin;
  v.x.assign(start.x.data(), start.x.data() + start.x.size());
  return gait_point(gait, v, key, parameter);
}

WalkerPoint walker_point(const walker::GaitOptimum& opt, storage::PointKey key, double parameter,
                         std::optional<records::KktSensitivitiesRecord> sensitivities) {
  records::WalkerPointRecord v = optimum_values(opt);
  v.sensitivities = std::move(sensitivities);
  return optimum_point(opt, v, key, parameter);
}

WalkerPoint walker_point(const continuation::ParametricProblem& family, const continuation::CurvePoint& c,
                         storage::PointKey key) {
  const std::unique_ptr<nlp::Problem> problem = family.at(c.parameter);
  walker::GaitOptimum opt;
  opt.summary = c.corrector;
  opt.z = c.x;
  opt.gait = dynamic_cast<const walker::GaitProblem&>(*problem).gait_at(c.x);
  opt.start = c.predictor_attempts > 0 ? "QP predictor" : "previous point";
  records::WalkerPointRecord v = optimum_values(opt);
  v.continuation = continuation_step_record(c);
  return optimum_point(opt, v, key, c.parameter);
}

storage::SolutionPoint point_of(const walker::PeriodicGait<double>& gait, const walker::GaitStart& start,
                                storage::PointKey key, double parameter) {
  return walker_point(gait, start, key, parameter).stored();
}

storage::SolutionPoint point_of(const walker::GaitOptimum& opt, storage::PointKey key, double parameter,
                                std::optional<records::KktSensitivitiesRecord> sensitivities) {
  return walker_point(opt, key, parameter, std::move(sensitivities)).stored();
}

bool CurveStore::operator()(const continuation::CurvePoint& c) {
  // A solve the job stopped (cancel, shutdown) is no result: stored, it would stand for the point
  // in a resumed attempt, which computes only the points not stored.
  if (c.corrector.termination == nlp::Termination::user_stop) return false;
  const int curve = c.curve_id + offset_;
  if (!counts_.count(curve)) ctx_.add_curve(curve, "solution curve " + std::to_string(curve), family_.parameter_name);
  const int index = counts_[curve]++;
  WalkerPoint w = point(c, {curve, index});
  w.row.required = grid_points_required_ && c.on_grid;
  ctx_.store_point(w.stored());
  return ctx_.stop_reason() == service::StopReason::none;
}

}  // namespace cyclopt::jobs
