#pragma once
// The one-step (Poincare) map of a sequence of giant swings and its Floquet multipliers.
//
// Under a 2 pi-periodic hip torque M_alpha(phi) the system is autonomous, and phi = 0 (mod 2 pi)
// is a Poincare section crossed once per swing. The one-step map P takes the section state
// s = (phi', alpha, alpha') at phi = 0 to the one at phi = 2 pi (seed 000, ch. 5.2: a periodic
// sequence is a fixed point of P). Its Jacobian comes from the variational equations
// Phi' = (df/dx) Phi along the swing (df/dx exact by ad::Dual<4>), projected onto the section:
//   DP = (I - f(x_T) e_phi^T / phi'(x_T)) Phi(T)   restricted to (phi', alpha, alpha').
// The eigenvalues of DP at a fixed point are the nontrivial Floquet multipliers of the periodic
// motion (the fourth, along the flow, is 1); |lambda| > 1 explains why the seed's open-loop
// sequences break off after a few swings (ch. 5.2).

#include "cyclopt/giant_swing/swing_simulation.hpp"

#include <Eigen/Core>

namespace cyclopt::giant_swing {

// (phi', alpha, alpha') on the section phi = 0 mod 2 pi.
using SectionState = Eigen::Vector3d;

inline State<double> state_on_section(const SectionState& s) { return State<double>(0.0, s[1], s[0], s[2]); }

struct OneStep {
  bool ok = false;           // the swing stayed admissible and reached phi = 2 pi
  SectionState next = SectionState::Zero();
  RoundResult round;
  ode::IntegrationStats stats;
};

OneStep one_step_map(const Model& model, const HipTorqueLaw& torque, const SectionState& s,
                     const SimulationOptions& options);

struct OneStepJacobian {
  bool ok = false;
  SectionState next = SectionState::Zero();
  Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();  // d next / d s
  ode::IntegrationStats stats;
};

// By the variational equations (one integration of 4 + 16 states).
OneStepJacobian one_step_jacobian(const Model& model, const HipTorqueLaw& torque, const SectionState& s,
                                  const SimulationOptions& options);

// By central differences of one_step_map with steps h_i = relative_step (1 + |s_i|).
Eigen::Matrix3d one_step_jacobian_by_differences(const Model& model, const HipTorqueLaw& torque,
                                                 const SectionState& s, const SimulationOptions& options,
                                                 double relative_step = 1e-5);

Eigen::Vector3cd floquet_multipliers(const Eigen::Matrix3d& jacobian);

}  // namespace cyclopt::giant_swing
