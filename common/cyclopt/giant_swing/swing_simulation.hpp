#pragma once
// Forward simulation of consecutive giant swings under a hip torque M_alpha(phi) (seed 000,
// ch. 4.2-4.3): the state is integrated in time with the adaptive Cash-Karp scheme, together with
// the running integrals of the evaluation function (eq. 4.11-4.13), until phi reaches 2 pi n
// (end of round n) or the motion leaves the admissible ranges of ch. 4.2:
//   phi' > 0,   -pi/4 <= alpha <= pi/2,   |alpha''| <= limit.

#include "cyclopt/giant_swing/equations_of_motion.hpp"
#include "cyclopt/giant_swing/hip_torque_law.hpp"
#include "cyclopt/ode/cash_karp.hpp"

#include <Eigen/Core>

#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace cyclopt::giant_swing {

struct AdmissibleRanges {
  double alpha_min = -std::numbers::pi / 4.0;  // rad
  double alpha_max = std::numbers::pi / 2.0;   // rad
  double alpha_acceleration_max = std::numeric_limits<double>::infinity();  // rad/s^2 (|alpha''|)
};

struct SimulationOptions {
  ode::CashKarpOptions integrator;
  AdmissibleRanges ranges;
  double max_round_time = 30.0;  // s; a round that takes longer counts as a failure
};

// Values at the end of one completed round (phi = 2 pi n) and the round's integrals.
struct RoundResult {
  double phi_rate = 0.0;    // rad/s
  double alpha = 0.0;       // rad
  double alpha_rate = 0.0;  // rad/s
  double duration = 0.0;    // s
  double friction_loss = 0.0;    // J, -int M_R phi' dt >= 0 (eq. 4.11)
  double jerk = 0.0;             // rad^2/s^5, 1/2 int (alpha''')^2 dt (eq. 4.12)
  double torque_integral = 0.0;  // Nm^2 s, 1/2 int M_alpha^2 dt (eq. 4.13)
};

struct SimulationResult {
  std::vector<RoundResult> rounds;  // completed rounds
  bool failed = false;              // left the admissible ranges (or the integrator gave up)
  double failure_phi = 0.0;         // phi_x where it failed (eq. 4.9)
  std::string failure_reason;       // empty unless failed
  ode::IntegrationStats stats;
};

// The integrated state: x (4), then the integrals of eq. 4.11-4.13.
using AugmentedState = Eigen::Matrix<double, 7, 1>;

// alpha''' along the motion: the time derivative of alpha''(x, M_alpha(phi)), by a Dual<1> seeded
// with x' (the hip torque's slope enters through phi).
double hip_jerk(const Model& model, const HipTorqueLaw& torque, const State<double>& x);

// Simulates up to `rounds` consecutive swings from x0 (phi0 = 0) under the hip torque law. observe(t, y) sees every
// accepted step (optional).
SimulationResult simulate_swings(const Model& model, const HipTorqueLaw& torque, const State<double>& x0, int rounds,
                                 const SimulationOptions& options,
                                 const std::function<void(double, const AugmentedState&)>& observe = {});

}  // namespace cyclopt::giant_swing
