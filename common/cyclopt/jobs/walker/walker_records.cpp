#include "cyclopt/jobs/walker/walker_records.hpp"

namespace cyclopt::jobs {

namespace {

std::vector<double> as_vector(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

std::vector<std::vector<double>> rows_of(const Eigen::MatrixXd& m) {
  std::vector<std::vector<double>> rows;
  for (Eigen::Index r = 0; r < m.rows(); ++r) rows.push_back(as_vector(m.row(r).transpose()));
  return rows;
}

}  // namespace

records::GaitRecord gait_record(const walker::PeriodicGait<double>& g) {
  records::GaitRecord r;
  r.real = g.real;
  if (!g.real) {
    r.failure = g.failure;
    return r;
  }
  r.objective = g.objective;
  r.f_mech = g.f_mech;
  r.f_usq = g.f_usq;
  r.mean_speed = g.mean_speed;
  r.step_length = g.step_length;
  r.step_period = g.step_period;
  r.floquet_multiplier = g.floquet;
  r.stable = g.floquet > 0.0 && g.floquet < 1.0;  // eq. (5.90)
  r.impact_energy_loss = g.impact_energy_loss;
  r.max_inequality = g.inequalities.maxCoeff();
  r.speed_equality = g.speed_equality;
  r.theta_plus = g.theta_plus;
  r.theta_minus = g.theta_minus;
  r.bezier_coefficients = rows_of(g.constraints.alpha);
  return r;
}

std::optional<records::GaitTrajectoryRecord> trajectory_record(const walker::GaitTrajectory<double>& t) {
  if (t.time.size() == 0) return std::nullopt;
  records::GaitTrajectoryRecord r;
  r.time = as_vector(t.time);
  r.theta = as_vector(t.theta);
  r.q = rows_of(t.q);
  r.q_dot = rows_of(t.q_dot);
  r.torque = rows_of(t.torque);
  r.contact_force = rows_of(t.contact_force);
  r.hip = rows_of(t.hip);
  r.swing_contact = rows_of(t.swing_contact);
  r.stance_foot_angle = as_vector(t.stance_foot_angle);
  return r;
}

records::SolverRecord solver_record(const nlp::SolverSummary& s) {
  records::SolverRecord r;
  r.termination = nlp::to_string(s.termination);
  r.success = s.success();
  r.message = s.message;
  r.iterations = s.iterations;
  r.function_evaluations = s.function_evaluations;
  r.jacobian_evaluations = s.jacobian_evaluations;
  r.failed_evaluations = s.failed_evaluations;
  r.wall_seconds = s.wall_seconds;
  r.objective = s.objective;
  r.kkt_error = s.kkt_error;
  r.constraint_violation = s.constraint_violation;
  r.x = as_vector(s.x);
  return r;
}

records::ContinuationStepRecord continuation_step_record(const continuation::CurvePoint& p) {
  return {.curve_id = p.curve_id,
          .on_grid = p.on_grid,
          .converged = p.converged,
          .predictor_attempts = p.predictor_attempts,
          .predictor_steps = p.predictor_steps,
          .kappa = p.kappa,
          .trust_region = p.trust_region,
          .point_seconds = p.seconds};
}

std::optional<records::KktSensitivitiesRecord> sensitivities_record(const std::optional<studies::OptimumSensitivities>& s) {
  if (!s) return std::nullopt;
  records::KktSensitivitiesRecord r;
  r.multipliers = s->multipliers;
  const studies::KktSensitivity& k = s->kkt;
  if (s->evaluated) {
    r.objective = k.objective;
    r.lagrangian_gradient = k.lagrangian_gradient;
    r.seconds = k.seconds;
  }
  r.unavailable = s->unavailable;
  if (r.unavailable) return r;
  r.active_constraints = k.active_constraints;
  r.unique_multipliers = k.unique_multipliers;
  r.weakly_active = k.weakly_active;
  const auto change = [](const studies::ActiveSetChange& c) {
    return records::ActiveSetChangeRecord{.relative_change = c.relative_change, .constraint = c.constraint, .enters = c.enters};
  };
  for (const studies::ParameterSensitivity& p : k.parameters)
    r.parameters.push_back({.name = p.name,
                            .value = p.value,
                            .derivative = p.derivative,
                            .relative = p.relative,
                            .kink = p.kink,
                            .decrease = change(p.decrease),
                            .increase = change(p.increase),
                            .weakly_active = p.weakly_active});
  return r;
}

}  // namespace cyclopt::jobs
