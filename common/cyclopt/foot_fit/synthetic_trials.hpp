#pragma once
// Ground truth without a gait lab: marker trials of a known foot rolling on flat ground with a
// given foot-angle history (seed 001, eq. 3.9-3.10a: x_A = F(theta) + x_0, z_A = F'(theta)),
// sampled at a chosen rate, with Gaussian marker noise, an offset along the walking direction
// and optional swing phases before heel strike and after toe-off.

#include "cyclopt/foot/foot_spec.hpp"
#include "cyclopt/foot_fit/marker_trial.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace cyclopt::foot_fit {

// One knot of a piecewise-linear foot-angle history theta_F(t); t = 0 is heel strike.
struct FootAngleKnot {
  double t;      // s
  double theta;  // rad
};

struct SyntheticTrialOptions {
  std::vector<FootAngleKnot> foot_angle;  // empty: default_foot_angle_history(foot)
  double rate = 200.0;                    // Hz
  double noise = 0.0;                     // m, standard deviation per marker coordinate
  // Ankle position along the walking direction at theta = 0, i.e. the x_off of eq. (4.16):
  // the ankle is at offset + F(theta) - F(0).
  double offset = 0.0;
  double walking_direction = 0.0;   // rad, in the horizontal plane (as AnkleTrackOptions)
  double lateral = 0.0;             // m, sideways position of the ankle
  double malleolus_spacing = 0.07;  // m between the two malleolus markers (mean = ankle, eq. 4.1)
  double swing_time = 0.0;          // s of swing before heel strike and after toe-off
  double swing_speed = 4.0;         // m/s of the ankle while swinging
  double body_force = 700.0;        // N in the "Fz" column while the foot rolls, 0 otherwise
  int vertical_axis = 2;            // file axis that points up
  std::vector<std::string> markers = {"LMAL", "MMAL"};  // lateral, medial
  std::uint64_t seed = 1;           // of the noise generator
  std::string source = "synthetic";
};

// A rolling history that crosses the heel, flat-foot and forefoot phases of the model (and the
// toe segment of HMT): -0.35 rad at heel strike, flat near 0 in mid stance, toe-off 0.9 rad (HM)
// or gamma_F + 0.35 rad (HMT), clipped to the foot's admissible angles.
std::vector<FootAngleKnot> default_foot_angle_history(const foot::FootSpec& foot);

// The trial; throws std::invalid_argument naming the option (knots not increasing in time or
// outside the admissible angles, rate or noise out of range, the point foot).
MarkerTrial synthetic_trial(const foot::FootSpec& foot, const SyntheticTrialOptions& options);

// The ankle of `foot` along the walking direction and above ground at theta (no noise).
Eigen::Vector2d synthetic_ankle(const foot::FootSpec& foot, double theta, double offset);

}  // namespace cyclopt::foot_fit
