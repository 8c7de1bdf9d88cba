#include "cyclopt/walker/forward_simulation.hpp"

#include "cyclopt/walker/bezier_basis.hpp"

#include <Eigen/LU>

namespace cyclopt::walker {

namespace {

// q_b,d and its first two derivatives with respect to theta (eq. 5.50-5.52), any theta.
struct Desired {
  Eigen::VectorXd q, dq, ddq;
};

Desired desired(const VirtualConstraints<double>& vc, double theta) {
  const double span = vc.theta_minus - vc.theta_plus;
  const auto B = bezier_basis_at(static_cast<int>(vc.alpha.cols()) - 1, (theta - vc.theta_plus) / span);
  return {vc.alpha * B.col(0), vc.alpha * B.col(1) / span, vc.alpha * B.col(2) / (span * span)};
}

struct Closure {
  const WalkerModel<double>& m;
  const VirtualConstraints<double>& vc;
  const SimulationOptions& o;

  // Accelerations and torques of the controlled system at (q, q_dot).
  void accelerations(const CoordinateVector<double>& q, const CoordinateVector<double>& qd, CoordinateVector<double>& qdd,
                     JointVector<double>& u) const {
    const int nb = m.joint_count;
    const StanceFrame<double> f = stance_frame(m, q);
    const CoordinateMatrix<double> M = mass_matrix(m, f);
    const CoordinateVector<double> gamma =
        generalized_forces(m, f, qd, CoordinateVector<double>(CoordinateVector<double>::Zero(nb + 1)));
    const Desired d = desired(vc, q(0));
    const Eigen::VectorXd y = q.tail(nb) - d.q, y_dot = qd.tail(nb) - d.dq * qd(0);
    // q_b_dd = r + d.dq theta_dd with r = q_b,d'' theta_dot^2 - K_P y - K_D y_dot (5.66-5.67)
    const Eigen::VectorXd r = d.ddq * (qd(0) * qd(0)) - o.kp * y - o.kd * y_dot;
    const double theta_dd = -(gamma(0) + M.row(0).tail(nb).dot(r)) / (M(0, 0) + M.row(0).tail(nb).dot(d.dq));
    qdd.resize(nb + 1);
    qdd(0) = theta_dd;
    qdd.tail(nb) = r + d.dq * theta_dd;
    u = (M * qdd + gamma).tail(nb);  // (5.35)
  }
};

double total_energy(const WalkerModel<double>& m, const CoordinateVector<double>& q, const CoordinateVector<double>& qd) {
  const StanceFrame<double> f = stance_frame(m, q);
  return kinetic_energy(m, f, qd) + potential_energy(m, f);
}

}  // namespace

StepSimulation simulate_step(const WalkerModel<double>& m, const VirtualConstraints<double>& vc, const Eigen::VectorXd& q0,
                             const Eigen::VectorXd& q_dot0, const SimulationOptions& o) {
  const int nq = m.coordinate_count(), nb = m.joint_count;
  const Closure cl{m, vc, o};
  // State [q; q_dot; E_mech; E_usq; W].
  const ode::RightHandSide rhs = [&](double, const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
    const CoordinateVector<double> q = y.head(nq), qd = y.segment(nq, nq);
    CoordinateVector<double> qdd;
    JointVector<double> u;
    cl.accelerations(q, qd, qdd, u);
    dy.resize(y.size());
    dy.head(nq) = qd;
    dy.segment(nq, nq) = qdd;
    const Eigen::ArrayXd power = u.array() * qd.tail(nb).array();
    dy(2 * nq) = power.max(0.0).sum();
    dy(2 * nq + 1) = m.constants.actuator_constant * u.squaredNorm();
    dy(2 * nq + 2) = power.sum();
  };
  // z_C2, armed once the swing foot is clearly airborne (it starts on the ground).
  bool airborne = false;
  const ode::EventFunction touchdown = [&](double, const Eigen::VectorXd& y) {
    const StanceFrame<double> f = stance_frame(m, CoordinateVector<double>(y.head(nq)));
    const double z = swing_contact_point(m, f).y();
    if (z > 1e-4) airborne = true;
    return airborne ? z : 1.0;
  };
  Eigen::VectorXd y0(2 * nq + 3);
  y0 << q0, q_dot0, 0.0, 0.0, 0.0;

  StepSimulation s;
  s.integration = ode::integrate(rhs, 0.0, y0, o.max_time, o.integrator, touchdown);
  if (!s.integration.event) {
    s.failure = "swing foot did not land within " + std::to_string(o.max_time) + " s (" + s.integration.message + ")";
    return s;
  }
  const Eigen::VectorXd& y = s.integration.y;
  s.q_minus = y.head(nq);
  s.q_dot_minus = y.segment(nq, nq);
  const CoordinateVector<double> q_minus = s.q_minus, qd_minus = s.q_dot_minus;
  const StanceFrame<double> f0 = stance_frame(m, CoordinateVector<double>(q0)), f1 = stance_frame(m, q_minus);
  const Vec2<double> c1 = m.has_feet() ? Vec2<double>(f1.stance_ankle + Vec2<double>(f1.stance_foot.ddF, -f1.stance_foot.dF))
                                       : f1.stance_ankle;
  if (!(swing_contact_point(m, f1).x() > c1.x())) {
    s.failure = "swing foot landed behind the stance foot (eq. 5.47)";
    return s;
  }
  s.landed = true;
  s.step_period = s.integration.t;
  s.step_length = point_position(f1, m.hip).x() - point_position(f0, m.hip).x();
  s.mechanical_energy = y(2 * nq);
  s.squared_torque = y(2 * nq + 1);
  s.actuator_work = y(2 * nq + 2);
  s.energy_change = total_energy(m, q_minus, qd_minus) - total_energy(m, CoordinateVector<double>(q0),
                                                                      CoordinateVector<double>(q_dot0));
  const ImpactResult<double> imp = impact_map(m, q_minus, qd_minus);
  s.impact_energy_loss = imp.kinetic_energy_minus - imp.kinetic_energy_plus;
  s.q_plus = imp.q_plus;
  s.q_dot_plus = imp.q_dot_plus;
  return s;
}

}  // namespace cyclopt::walker
