#include "cyclopt/io/gait_json.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace cyclopt::io {

namespace {

std::vector<double> as_vector(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

nlohmann::json rows_of(const Eigen::MatrixXd& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < m.rows(); ++r) rows.push_back(as_vector(m.row(r).transpose()));
  return rows;
}

}  // namespace

nlohmann::json gait_to_json(const walker::PeriodicGait<double>& g, bool trajectories) {
  nlohmann::json j;
  j["real"] = g.real;
  if (!g.real) {
    j["failure"] = g.failure;
    return j;
  }
  j["objective"] = g.objective;
  j["f_mech"] = g.f_mech;
  j["f_usq"] = g.f_usq;
  j["mean_speed"] = g.mean_speed;
  j["step_length"] = g.step_length;
  j["step_period"] = g.step_period;
  j["floquet_multiplier"] = g.floquet;
  j["stable"] = g.floquet > 0.0 && g.floquet < 1.0;  // eq. (5.90)
  j["impact_energy_loss"] = g.impact_energy_loss;
  j["max_inequality"] = g.inequalities.maxCoeff();
  j["speed_equality"] = g.speed_equality;
  j["theta_plus"] = g.theta_plus;
  j["theta_minus"] = g.theta_minus;
  j["bezier_coefficients"] = rows_of(g.constraints.alpha);
  if (trajectories && g.trajectory.time.size() > 0) {
    const walker::GaitTrajectory<double>& t = g.trajectory;
    nlohmann::json tr;
    tr["time"] = as_vector(t.time);
    tr["theta"] = as_vector(t.theta);
    tr["q"] = rows_of(t.q);
    tr["q_dot"] = rows_of(t.q_dot);
    tr["torque"] = rows_of(t.torque);
    tr["contact_force"] = rows_of(t.contact_force);
    tr["hip"] = rows_of(t.hip);
    tr["swing_contact"] = rows_of(t.swing_contact);
    if (t.stance_foot_angle.size() > 0) tr["stance_foot_angle"] = as_vector(t.stance_foot_angle);
    j["trajectory"] = tr;
  }
  return j;
}

nlohmann::json summary_to_json(const nlp::SolverSummary& s) {
  return {{"termination", nlp::to_string(s.termination)}, {"success", s.success()}, {"message", s.message},
          {"iterations", s.iterations}, {"function_evaluations", s.function_evaluations},
          {"jacobian_evaluations", s.jacobian_evaluations}, {"failed_evaluations", s.failed_evaluations},
          {"wall_seconds", s.wall_seconds}, {"objective", s.objective}, {"kkt_error", s.kkt_error},
          {"constraint_violation", s.constraint_violation}, {"x", as_vector(s.x)}};
}

}  // namespace cyclopt::io
