#pragma once
// Every stance of one foot in a raw gait-lab recording: the rolling phases the fit of seed 001
// section 4.2 uses (the seed's trials start at first contact, eq. 4.5; a recording of several
// steps holds several). A stance is found from the vertical ground-reaction force of the plates
// the foot loads, or from the ankle's kinematics; one that the recording or a long gap in the
// ankle markers cuts is refused with the reason, never fitted.

#include "cyclopt/foot_fit/ankle_series.hpp"
#include "cyclopt/foot_fit/ground_reactions.hpp"

#include <string>
#include <utility>
#include <vector>

namespace cyclopt::foot_fit {

struct StanceOptions {
  double force_threshold = 20.0;  // N: loaded plate (eq. 4.5 takes F != 0; 20 N is above plate noise)
  // Kinematic rule: a stance is a run of frames in which the ankle moves slower than
  // max_rolling_speed and that holds a frame slower than still_speed (the flat foot); its offsets
  // from force plates: bench/results/foot_fit_real_data.txt.
  double max_rolling_speed = 2.0;  // m/s
  double still_speed = 0.25;       // m/s
  // A plate's loaded run belongs to this foot when its centre of pressure stays within this
  // horizontal distance of the ankle (median over the run): a shod foot reaches ~0.1 m behind
  // and ~0.2 m in front of the ankle, the other foot is a step length or a stride width away.
  double max_cop_distance = 0.25;  // m
  int min_samples = 10;            // a stance with fewer frames is refused
};

struct Stance {
  int first = 0, last = 0;  // frames of the recording (0-based samples), inclusive
  double start = 0.0, end = 0.0;  // s
  std::string rule;     // "force ground_force_r_", "force Fz", "kinematics", "interval"
  // Bounded by measured contact (a loaded plate): the rolling phase lies within [start, end].
  bool contact = false;
  std::string refusal;  // why it is not fitted; empty for a complete stance
  bool complete() const { return refusal.empty(); }
};

// A recording of one foot: its ankle and the stances found, complete or refused, in time order.
struct GaitTrial {
  AnkleSeries ankle;
  std::vector<Stance> stances;
  int complete_stances() const;
};

// Stances from force channels. With `by_centre_of_pressure` a loaded run counts only when the
// channel's centre of pressure is near the ankle (channels without one then count always).
// Refused: a run loaded at the first or last force sample, or reaching beyond the ankle
// markers' data (cut by the recording), holding an unfilled gap, or too short.
std::vector<Stance> force_stances(const AnkleSeries& ankle, const std::vector<ForceChannel>& channels,
                                  bool by_centre_of_pressure, const StanceOptions& options = {});

// Stances from the kinematic rule; refused: a run that reaches the first or last frame with the
// ankle markers or an unfilled gap (the foot may have been on the ground before or after).
std::vector<Stance> kinematic_stances(const AnkleSeries& ankle, const StanceOptions& options = {});

// The first and last frame within [t0, t1] ({-1, -1} when none); throws std::invalid_argument
// when t0 >= t1.
std::pair<int, int> frames_within(const AnkleSeries& ankle, double t0, double t1);

// The frames within [t0, t1] as one stance (a hand-given interval: not checked for being cut).
// Throws std::invalid_argument when t0 >= t1; the stance is refused when it holds an unfilled
// gap or too few frames.
Stance interval_stance(const AnkleSeries& ankle, double t0, double t1, const StanceOptions& options = {});

}  // namespace cyclopt::foot_fit
