#pragma once
// Semi-analytic periodic gait of the hybrid zero dynamics and everything reconstructed from it
// (seed 001 sections 5.2.4-5.4): eq. (5.76)-(5.90) on the grid (5.93), states (5.94-5.97), torques
// (5.35), contact force (5.14), impact impulse (5.28), electric power (5.98-5.100), objectives
// (5.101-5.102) with the zero-crossing correction of Fig. 5.3, the speed equality (5.103) and the
// 10P+3 inequalities (5.104).
//
// Templated on the scalars of the model (MT) and of x: double for values, ad::Dual<N> for exact
// derivatives with respect to the gait parameters x (double model) and/or model parameters (Dual
// model), std::complex<double> for complex-step checks. The gait's scalar is the two combined.

#include "cyclopt/walker/bezier_basis.hpp"
#include "cyclopt/walker/grid_point.hpp"
#include "cyclopt/walker/positive_power.hpp"
#include "cyclopt/walker/quadrature.hpp"
#include "cyclopt/walker/virtual_constraints.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace cyclopt::walker {

enum class Objective { mechanical, squared_torque };  // f_mech (5.102), f_usq (5.101)

struct GaitOptions {
  Objective objective = Objective::mechanical;
  double speed = 1.3;             // target mean speed v_bar (m/s), eq. (5.103)
  bool keep_trajectories = true;  // fill PeriodicGait::trajectory
  Quadrature quadrature = Quadrature::trapezoid;  // for iota, int mu2/iota, time and f_usq (5.80-5.96)
  // W, >= 0: f_mech's positive part (5.100) rounded on |u q_dot| < band (positive_power.hpp); 0: the
  // seed's rule. Trapezoid rule only.
  double positive_power_band = 0.0;
  // W, >= 0: f_mech's positive part smoothed to (p + sqrt(p^2 + e^2)) / 2 (positive_power.hpp), the
  // integrand of the smoothing homotopy; 0: not smoothed. Trapezoid rule only, not with a band.
  double positive_power_smoothing = 0.0;
};

// Indices into the inequality vector (eq. 5.104) for a given P.
struct InequalityLayout {
  int points;
  int impulse() const { return 0; }                        // (a), (b): 3 entries
  int normal_force() const { return 3; }                   // (c): P
  int friction() const { return 3 + points; }              // (d): 2P
  int swing_clearance() const { return 3 + 3 * points; }   // (e): 2 + (P-2)
  int knee_lower() const { return 3 + 4 * points; }        // (f): 2P
  int knee_upper() const { return 3 + 6 * points; }        // (g): 2P
  int torso() const { return 3 + 8 * points; }             // (h): 2P
  int size() const { return 3 + 10 * points; }
};

template <class T>
using Matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
template <class T>
using Vector = Eigen::Matrix<T, Eigen::Dynamic, 1>;

// Reconstructed states on the P grid points (columns).
template <class T>
struct GaitTrajectory {
  Vector<T> theta, time;            // phase variable, time since impact (s)
  Vector<T> zeta;                   // zeta = sigma^2 / 2 (eq. 5.75)
  Matrix<T> q, q_dot, q_ddot;       // q_s = [theta; q_b] and derivatives, (n_b+1) x P
  Matrix<T> torque;                 // u (N m), n_b x P, eq. (5.35)
  Matrix<T> contact_force;          // F_1 = [F_1x; F_1z] (N), 2 x P, eq. (5.14)
  Matrix<T> hip;                    // [x_H; z_H] (m), stance ankle at x_0 = 0
  Matrix<T> swing_contact;          // [x_C2; z_C2] (m)
  Vector<T> stance_foot_angle;      // theta_F1 (rad), feet only
};

template <class T>
struct PeriodicGait {
  bool real = false;           // a real periodic solution exists (eq. 5.87) and was reconstructed
  std::string failure;         // why not, with where
  int failure_point = -1;      // grid index where it failed (eq. 5.87), -1 if not point-specific
  T objective{}, f_mech{}, f_usq{};
  T speed_equality{};          // c_g (eq. 5.103)
  Vector<T> inequalities;      // c_u <= 0 (eq. 5.104); forces scaled by m g, impulses by m (1 m/s)
  Matrix<T> joint_power;       // u_j q_dot_j (W) whose positive part f_mech integrates (5.100): joints x grid points
  Vector<T> interval_duration; // t_i+1 - t_i (s): the intervals of the trapezoid rule in time (P - 1)
  T step_length{}, step_period{}, mean_speed{};
  T floquet{};                 // Lambda (eq. 5.89)
  T zeta_plus{};               // zeta+ (eq. 5.85)
  T impact_energy_loss{};      // E_kin- - E_kin+ at the impact (J)
  Vec2<T> impulse;             // F_hat_2 (N s)
  T theta_plus{}, theta_minus{};
  VirtualConstraints<T> constraints;
  GaitTrajectory<T> trajectory;
};

template <class MT, class XVector, class T = ad::promoted_t<MT, typename XVector::Scalar>>
PeriodicGait<T> periodic_gait(const WalkerModel<MT>& m, const BezierBasis& basis, const XVector& x,
                              const GaitOptions& opt) {
  using std::exp, std::sqrt, std::abs;
  constexpr double pi = std::numbers::pi;
  const int nb = m.joint_count, nq = nb + 1, P = static_cast<int>(basis.s.size());
  PeriodicGait<T> g;
  g.constraints = virtual_constraints(m, x);
  if (!g.constraints.ok) {
    g.failure = g.constraints.failure;
    return g;
  }
  const VirtualConstraints<T>& vc = g.constraints;
  g.theta_plus = vc.theta_plus;
  g.theta_minus = vc.theta_minus;
  const T span = vc.theta_minus - vc.theta_plus, h = span / double(P - 1);
  const Matrix<T> qb = bezier_combination(vc.alpha, basis.value);
  const T inv_span = 1.0 / span;
  const Matrix<T> qb1 = bezier_combination(vc.alpha, basis.first) * inv_span;
  const Matrix<T> qb2 = bezier_combination(vc.alpha, basis.second) * T(inv_span * inv_span);

  // Dynamics on the constraint at every grid point (eq. 5.73, 5.76), and what the reconstruction
  // needs of the stance frame (grid_point.hpp), plus the swing contact velocity per unit theta_dot
  // at both ends.
  Matrix<T> hip(2, P), swing_contact(2, P);
  Vector<T> stance_foot_angle(m.has_feet() ? P : 0);
  std::vector<GridPoint<T>> points(P);
  std::vector<ZeroDynamicsCoefficients<T>> zd(P);
  Vector<T> theta(P), mu1(P), mu2(P);
  Vec2<T> unit_swing_velocity_plus = Vec2<T>::Zero(), unit_swing_velocity_minus = Vec2<T>::Zero();
  CoordinateVector<T> q(nq), gamma(nq), gamma1(nq);
  for (int i = 0; i < P; ++i) {
    theta(i) = vc.theta_plus + h * double(i);
    q(0) = theta(i);
    q.tail(nb) = qb.col(i);
    gamma(0) = T(1.0);
    gamma.tail(nb) = qb1.col(i);
    gamma1(0) = T(0.0);
    gamma1.tail(nb) = qb2.col(i);
    GridPoint<T>& point = points[i];
    grid_point(m, q, gamma, gamma1, point);
    zd[i] = zero_dynamics_coefficients(point.dynamics);
    if (!(ad::value(zd[i].a) > 0.0)) {
      g.failure = "singular zero dynamics: e_1^T M_s gamma <= 0 at grid point " + std::to_string(i) + " (theta = " +
                  std::to_string(ad::value(theta(i))) + " rad)";
      g.failure_point = i;
      return g;
    }
    mu1(i) = -2.0 * zd[i].nu3 / zd[i].nu1;
    mu2(i) = zd[i].nu2 / zd[i].nu1;
    hip.col(i) = point.hip;
    swing_contact.col(i) = point.swing_contact;
    if (m.has_feet()) stance_foot_angle(i) = point.stance_foot_angle;
    if (i == 0 || i == P - 1)
      (i == 0 ? unit_swing_velocity_plus : unit_swing_velocity_minus) =
          swing_contact_velocity(m, stance_frame(m, q), slot_rates(m, gamma));
  }
  // Cumulative quadrature for iota (5.80, kept as its logarithm) and int mu2/iota (5.84).
  const Vector<T> log_iota = -cumulative_integral(mu1, h, opt.quadrature);
  Vector<T> iota(P), mu2_over_iota(P);
  for (int i = 0; i < P; ++i) {
    iota(i) = exp(log_iota(i));
    mu2_over_iota(i) = mu2(i) / iota(i);
  }
  const Vector<T> I = cumulative_integral(mu2_over_iota, h, opt.quadrature);
  // Impact map of the zero dynamics (5.77) and the fixed point (5.85), Floquet multiplier (5.89).
  const T delta_z = vc.theta_dot_ratio * zd[P - 1].nu1 / zd[0].nu1;
  g.floquet = delta_z * delta_z * iota(P - 1);
  if (std::abs(1.0 - ad::value(g.floquet)) < 1e-12) {
    g.failure = "Floquet multiplier Lambda = 1: no isolated periodic orbit (eq. 5.85 singular)";
    return g;
  }
  g.zeta_plus = g.floquet * I(P - 1) / (1.0 - g.floquet);
  // Real-solution check (5.87): zeta+ + int mu2/iota > 0 on the whole step.
  for (int i = 0; i < P; ++i)
    if (!(ad::value(g.zeta_plus + I(i)) > 0.0)) {
      g.failure = "no real solution: zeta <= 0 at grid point " + std::to_string(i) + " of " + std::to_string(P) +
                  " (theta = " + std::to_string(ad::value(theta(i))) + " rad, zeta+ = " +
                  std::to_string(ad::value(g.zeta_plus)) + "), eq. 5.87";
      g.failure_point = i;
      return g;
    }

  // States on the grid (5.84, 5.86 with sigma = sqrt(2 zeta), 5.95-5.97), torques (5.35) and
  // contact force (5.14) from the affine forms of ConstrainedDynamics, and time (5.96).
  GaitTrajectory<T>& tr = g.trajectory;
  tr.theta = theta;
  tr.hip = std::move(hip);
  tr.swing_contact = std::move(swing_contact);
  tr.stance_foot_angle = std::move(stance_foot_angle);
  tr.zeta.resize(P);
  tr.time.resize(P);
  tr.q.resize(nq, P);
  tr.q_dot.resize(nq, P);
  tr.q_ddot.resize(nq, opt.keep_trajectories ? P : 0);  // only a trajectory output
  tr.torque.resize(nb, P);
  tr.contact_force.resize(2, P);
  Vector<T> theta_dot(P);
  const Vec2<T> weight(T(0.0), T(m.total_mass * m.constants.gravity));
  for (int i = 0; i < P; ++i) {
    tr.zeta(i) = iota(i) * (g.zeta_plus + I(i));
    const T sigma = sqrt(2.0 * tr.zeta(i));  // eq. (5.86) prints 2 sqrt(zeta); zeta = sigma^2/2 (5.75) gives this
    theta_dot(i) = zd[i].nu1 * sigma;
    const T theta_dot_sq = theta_dot(i) * theta_dot(i);
    const T theta_ddot = -(zd[i].b * theta_dot_sq + zd[i].c) / zd[i].a;
    tr.q(0, i) = theta(i);
    tr.q.col(i).tail(nb) = qb.col(i);
    tr.q_dot(0, i) = theta_dot(i);
    tr.q_dot.col(i).tail(nb) = qb1.col(i) * theta_dot(i);
    if (opt.keep_trajectories) {
      tr.q_ddot(0, i) = theta_ddot;
      tr.q_ddot.col(i).tail(nb) = qb1.col(i) * theta_ddot + qb2.col(i) * theta_dot_sq;
    }
    const ConstrainedDynamics<T>& cd = points[i].dynamics;
    tr.torque.col(i) = cd.inertial.tail(nb) * theta_ddot + cd.coupled.tail(nb) * theta_dot_sq + cd.gravity.tail(nb);
    tr.contact_force.col(i) = cd.force_inertial * theta_ddot + cd.force_coupled * theta_dot_sq + weight;
  }
  const Vec2<T> swing_velocity_plus = unit_swing_velocity_plus * theta_dot(0);
  const Vec2<T> swing_velocity_minus = unit_swing_velocity_minus * theta_dot(P - 1);
  tr.time = cumulative_integral(Vector<T>(theta_dot.cwiseInverse()), h, opt.quadrature);  // (5.96)

  // Step, speed, impact (the unit impact scales linearly with theta_dot-).
  g.step_length = tr.hip(0, P - 1) - tr.hip(0, 0);
  g.step_period = tr.time(P - 1);
  g.mean_speed = g.step_length / g.step_period;
  g.speed_equality = g.mean_speed - T(opt.speed);
  const T td_minus = theta_dot(P - 1);
  g.impulse = vc.unit_impact.impulse * td_minus;
  g.impact_energy_loss = (vc.unit_impact.kinetic_energy_minus - vc.unit_impact.kinetic_energy_plus) * td_minus * td_minus;

  // Energy per step (5.98-5.102), the seed's rules: trapezoid in time with the zero-crossing
  // correction for f_mech (optionally rounded, positive_power.hpp), trapezoid in time for f_usq; corrected rules: in theta (dt = d theta /
  // theta_dot), positive_part_integral for f_mech and the corrected trapezoid for f_usq.
  const T weight_step = m.total_mass * T(m.constants.gravity) * g.step_length;
  const T c_A = T(m.constants.actuator_constant);
  // Joint powers u_j q_dot_j and sum_j u_j^2 once per grid point.
  Matrix<T> power(nb, P);
  Vector<T> usq(P), dt(P - 1);
  for (int i = 0; i < P; ++i) {
    for (int j = 0; j < nb; ++j) power(j, i) = tr.torque(j, i) * tr.q_dot(1 + j, i);
    usq(i) = ad::dot(tr.torque.col(i), tr.torque.col(i));
  }
  for (int i = 0; i + 1 < P; ++i) dt(i) = tr.time(i + 1) - tr.time(i);
  T e_mech = T(0.0), e_usq = T(0.0);
  if (opt.quadrature == Quadrature::trapezoid) {
    for (int j = 0; j < nb; ++j)
      for (int i = 0; i + 1 < P; ++i)
        e_mech += opt.positive_power_band > 0.0 ? rounded_positive_part_trapezoid(power(j, i), power(j, i + 1), dt(i),
                                                                                  opt.positive_power_band)
                  : opt.positive_power_smoothing > 0.0
                      ? smoothed_positive_part_trapezoid(power(j, i), power(j, i + 1), dt(i), opt.positive_power_smoothing)
                      : positive_part_trapezoid(power(j, i), power(j, i + 1), dt(i));
  } else {  // in theta: int max(p, 0) dt = int max(p / theta_dot, 0) d theta
    Vector<T> power_per_theta(P);
    for (int j = 0; j < nb; ++j) {
      for (int i = 0; i < P; ++i) power_per_theta(i) = power(j, i) / theta_dot(i);
      e_mech += positive_part_integral(power_per_theta, h);
    }
  }
  if (opt.quadrature == Quadrature::trapezoid) {
    for (int i = 0; i + 1 < P; ++i) e_usq += (usq(i) + usq(i + 1)) * dt(i);
    e_usq *= 0.5 * c_A;
  } else {
    Vector<T> usq_per_theta(P);
    for (int i = 0; i < P; ++i) usq_per_theta(i) = c_A * usq(i) / theta_dot(i);
    e_usq = cumulative_integral(usq_per_theta, h, opt.quadrature)(P - 1);
  }
  g.f_mech = e_mech / weight_step;
  g.joint_power = std::move(power);
  g.interval_duration = std::move(dt);
  g.f_usq = e_usq / weight_step;
  g.objective = opt.objective == Objective::mechanical ? g.f_mech : g.f_usq;

  // Inequalities (5.104). Forces are divided by the weight m g and impulses by m * (1 m/s) so all
  // entries are O(1); the feasible set is the seed's.
  const InequalityLayout L{P};
  const T mu = T(m.constants.friction), W = m.total_mass * T(m.constants.gravity), Wi = m.total_mass;
  Vector<T>& c = g.inequalities;
  c.resize(L.size());
  c(0) = -g.impulse.y() / Wi;                               // (a)
  c(1) = (-g.impulse.x() - mu * g.impulse.y()) / Wi;         // (b)
  c(2) = (g.impulse.x() - mu * g.impulse.y()) / Wi;
  for (int i = 0; i < P; ++i) {
    const T Fx = tr.contact_force(0, i) / W, Fz = tr.contact_force(1, i) / W;
    c(L.normal_force() + i) = -Fz;                           // (c)
    c(L.friction() + 2 * i) = -Fx - mu * Fz;                 // (d)
    c(L.friction() + 2 * i + 1) = Fx - mu * Fz;
    c(L.knee_lower() + 2 * i) = -tr.q(1 + joint_K1, i);      // (f)
    c(L.knee_lower() + 2 * i + 1) = -tr.q(1 + joint_K2, i);
    c(L.knee_upper() + 2 * i) = tr.q(1 + joint_K1, i) - 2.0 * pi / 3.0;  // (g)
    c(L.knee_upper() + 2 * i + 1) = tr.q(1 + joint_K2, i) - 2.0 * pi / 3.0;
    const T theta_T = torso_angle<T>(CoordinateVector<T>(tr.q.col(i)));
    c(L.torso() + 2 * i) = theta_T - pi / 2.0;               // (h); the seed prints "1/2 pi - theta_T",
    c(L.torso() + 2 * i + 1) = -pi / 2.0 - theta_T;          // its own text asks for -pi/2 <= theta_T
  }
  c(L.swing_clearance()) = -swing_velocity_plus.y();        // (e)
  c(L.swing_clearance() + 1) = swing_velocity_minus.y();
  for (int i = 1; i + 1 < P; ++i) c(L.swing_clearance() + 1 + i) = -tr.swing_contact(1, i);
  g.real = true;
  if (!opt.keep_trajectories) g.trajectory = {};
  return g;
}

}  // namespace cyclopt::walker
