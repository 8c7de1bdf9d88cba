#pragma once
// Time-domain simulation of one step of the closed-loop walker in physical coordinates, the
// independent check of the semi-analytic gait (seed 001 eq. 5.31-5.36, 5.63-5.67, 5.41-5.45).
//
// The single-support ODE M_s(q) q_dd + Gamma_s(q, q_d) = [0; u] (5.16/5.31) is integrated with
// Dormand-Prince 5(4) for the state [q_s; q_s_dot] plus the actuator energy integrals. The torques
// come from input/output linearisation: q_b_dd = v = q_b,d'' theta_d^2 + q_b,d' theta_dd - K_P y - K_D y_dot
// (5.66-5.67, y = q_b - q_b,d(theta)), solved together with the unactuated first row of (5.31)
// for theta_dd and u (5.34-5.35). The step ends when the swing contact point C2 reaches the ground
// from above (event z_C2 = 0, eq. 5.47); the plastic impact with leg swap (5.26, 5.41-5.43) gives
// the post-impact state.

#include "cyclopt/ode/dormand_prince.hpp"
#include "cyclopt/walker/virtual_constraints.hpp"

#include <string>

namespace cyclopt::walker {

struct SimulationOptions {
  ode::IntegratorOptions integrator;
  double kp = 400.0;      // K_P = kp I (1/s^2)
  double kd = 40.0;       // K_D = kd I (1/s)
  double max_time = 5.0;  // s, give up if the swing foot has not landed by then
};

struct StepSimulation {
  bool landed = false;            // swing foot reached the ground in front (eq. 5.47)
  std::string failure;
  double step_period = 0.0;       // s
  double step_length = 0.0;       // hip travel x_H- - x_H+ (m)
  double mechanical_energy = 0.0; // int sum max(u_i q_b_dot_i, 0) dt (J), eq. (5.100)
  double squared_torque = 0.0;    // int sum c_A u_i^2 dt (J), eq. (5.99)
  double actuator_work = 0.0;     // int sum u_i q_b_dot_i dt (J), signed
  double energy_change = 0.0;     // (E_kin + E_pot)(t-) - (E_kin + E_pot)(t+) over the single support (J)
  double impact_energy_loss = 0.0;  // E_kin- - E_kin+ of the impact (J)
  Eigen::VectorXd q_minus, q_dot_minus;  // before the impact
  Eigen::VectorXd q_plus, q_dot_plus;    // after the impact and leg swap
  ode::IntegrationResult integration;
};

// Simulates from (q_s, q_s_dot) at the start of a step under the virtual constraints `vc`.
StepSimulation simulate_step(const WalkerModel<double>& model, const VirtualConstraints<double>& vc,
                             const Eigen::VectorXd& q0, const Eigen::VectorXd& q_dot0, const SimulationOptions& options);

}  // namespace cyclopt::walker
