#include "cyclopt/walker/gait_shape.hpp"

#include "cyclopt/walker/virtual_constraints.hpp"

#include <Eigen/LU>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace cyclopt::walker {

namespace {

constexpr double pi = std::numbers::pi;

// alpha_tilde_M (eq. 5.55-5.56 inputs) for stance/swing thigh angles beta from the downward vertical.
Eigen::VectorXd impact_angles(const WalkerModel<double>& m, const GaitShape& s, double beta1, double beta2) {
  const int nb = m.joint_count;
  Eigen::VectorXd a(nb);
  a(joint_H1) = pi + beta1 - s.torso_lean;
  a(joint_H2) = pi - beta2 - s.torso_lean;
  a(joint_K1) = s.stance_knee;
  a(joint_K2) = s.swing_knee;
  if (m.has_feet()) {
    a(joint_A1) = m.foot_zero_angle + s.push_off_roll;     // absolute foot angles theta_F1-, theta_F2-
    a(joint_A2) = m.foot_zero_angle + s.heel_strike_roll;
  }
  return a;
}

// q_s- of the impact posture with torso angle s.torso_lean (eq. 5.48, 5.56).
CoordinateVector<double> impact_configuration(const WalkerModel<double>& m, const GaitShape& s, double beta1,
                                              double beta2) {
  const Eigen::VectorXd a = impact_angles(m, s, beta1, beta2);
  CoordinateVector<double> q(m.coordinate_count());
  q(0) = s.torso_lean + a(joint_H1) + 0.5 * a(joint_K1);  // eq. (5.48)
  q.tail(m.joint_count) = a;
  if (m.has_feet()) {
    q(1 + joint_A1) = a(joint_A1) - s.torso_lean - a(joint_H1) - a(joint_K1);  // eq. (5.56)
    q(1 + joint_A2) = a(joint_A2) - s.torso_lean - a(joint_H2) - a(joint_K2);
  }
  return q;
}

// Contact points C2 - C1 at the impact posture.
Eigen::Vector2d contact_offset(const WalkerModel<double>& m, const GaitShape& s, double beta1, double beta2) {
  const StanceFrame<double> f = stance_frame(m, impact_configuration(m, s, beta1, beta2));
  Vec2<double> c1 = f.stance_ankle;
  if (m.has_feet()) c1 += Vec2<double>(f.stance_foot.ddF, -f.stance_foot.dF);
  return swing_contact_point(m, f) - c1;
}

}  // namespace

Eigen::VectorXd gait_parameters(const WalkerModel<double>& m, const GaitShape& s) {
  if (!(s.contact_distance > 0.0 && s.contact_distance < 1.5))
    throw std::invalid_argument("shape.contact_distance: " + std::to_string(s.contact_distance) + " m outside (0, 1.5)");
  // Newton on (x_C2 - x_C1 - d, z_C2 - z_C1) = 0 over the thigh angles, central-difference Jacobian.
  const double leg = m.segments[l_O] + m.segments[l_U];
  double beta = std::asin(std::min(0.9, 0.5 * s.contact_distance / leg));
  Eigen::Vector2d b(beta, beta);
  auto residual = [&](const Eigen::Vector2d& v) {
    const Eigen::Vector2d c = contact_offset(m, s, v(0), v(1));
    return Eigen::Vector2d(c.x() - s.contact_distance, c.y());
  };
  Eigen::Vector2d r = residual(b);
  for (int it = 0; it < 50 && r.norm() > 1e-13; ++it) {
    Eigen::Matrix2d J;
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d e = Eigen::Vector2d::Zero();
      e(k) = 1e-6;
      J.col(k) = (residual(b + e) - residual(b - e)) / 2e-6;
    }
    b -= J.partialPivLu().solve(r);
    r = residual(b);
  }
  if (!(r.norm() < 1e-10) || std::abs(b(0)) > 1.2 || std::abs(b(1)) > 1.2)
    throw std::invalid_argument("shape.contact_distance: no posture with both feet on the ground at " +
                                std::to_string(s.contact_distance) + " m");

  const int nb = m.joint_count, M = m.constants.bezier_degree;
  Eigen::VectorXd x(gait_parameter_count(nb, M));
  x.tail(nb) = impact_angles(m, s, b(0), b(1));
  // alpha_M = q_b- and alpha_0 = q_b+ (eq. 5.57); interior coefficients in between.
  const CoordinateVector<double> q_minus = impact_configuration(m, s, b(0), b(1));
  const Eigen::VectorXd alpha_M = q_minus.tail(nb);
  // Joint rates per unit theta_dot just before the impact: thigh 1 and shank 1 turn with theta
  // (torso at rest, eq. 5.48), leg 2 at rest, foot 1 rolling at push_off_rate.
  Eigen::VectorXd rate = Eigen::VectorXd::Zero(nb);
  rate(joint_H1) = 1.0;
  if (m.has_feet()) rate(joint_A1) = s.push_off_rate - 1.0;
  const double span = q_minus(0) - swap_configuration(q_minus)(0);
  const Eigen::VectorXd alpha_M1 = alpha_M - (span / M) * rate;  // eq. (5.54b)
  x.segment((M - 3) * nb, nb) = alpha_M1;
  const VirtualConstraints<double> vc = virtual_constraints(m, x);  // alpha_1 from the impact (5.62)
  if (!vc.ok) throw std::invalid_argument("shape: impact posture admits no gait: " + vc.failure);
  for (int i = 2; i < M - 1; ++i) {
    const double t = double(i - 1) / (M - 2);
    Eigen::VectorXd ai = (1.0 - t) * vc.alpha.col(1) + t * alpha_M1;
    ai(joint_K2) += s.swing_knee_bump;
    x.segment((i - 2) * nb, nb) = ai;
  }
  return x;
}

}  // namespace cyclopt::walker
