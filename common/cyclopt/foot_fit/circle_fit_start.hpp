#pragma once
// Step 1 of seed 001 section 4.2: starting values for the HM fit from two circle fits. In the
// limit of sharp transitions the ankle of an HM foot moves on a circle about the heel H behind
// the lowest point and on one about M in front of it (Fig. 3.1b, 4.2).

#include "cyclopt/foot/foot_parameters.hpp"
#include "cyclopt/foot_fit/ankle_track.hpp"

#include <Eigen/Core>

#include <vector>

namespace cyclopt::foot_fit {

// A circle with its centre on the ground, fitted to ankle points (eq. 4.10).
struct GroundCircle {
  double centre = 0.0;  // x_neg or x_pos (m), relative to the lowest ankle point
  double radius = 0.0;  // R_neg or R_pos (m)
  int samples = 0;
  bool centre_on_bound = false;  // the constraint x_neg <= 0 / x_pos >= 0 was active
};

struct CircleFitStart {
  GroundCircle heel;      // J_neg (eq. 4.9): points behind the lowest one, centre x_neg <= 0
  GroundCircle forefoot;  // J_pos: points at or in front of it, centre x_pos >= 0
  double z_min = 0.0;     // m, min_k z_min,k (eq. 4.11a)
  std::vector<double> x_off;           // per trial: x of its lowest point (that point -> x = 0)
  foot::FootParameters<double> hm;     // h_F, l_HA, l_HM of eq. (4.11); k_H = k_M = 1e-8, k_HM = 0.1
  std::vector<Eigen::VectorXd> theta;  // per trial and sample, eq. (4.12)
};

// Throws std::invalid_argument when a side has fewer than three points (the rolling phase must
// include heel and forefoot contact) or a circle degenerates.
CircleFitStart circle_fit_start(const std::vector<AnkleTrack>& tracks);

// Minimises sum ((x - c)^2 + z^2 - R^2)^2 with c <= 0 (heel) or c >= 0 (forefoot), eq. (4.10):
// linear least squares in (2c, R^2 - c^2), whose constrained solution lies on c = 0 when the
// free one violates the bound.
GroundCircle fit_ground_circle(const std::vector<double>& x, const std::vector<double>& z, bool heel);

}  // namespace cyclopt::foot_fit
