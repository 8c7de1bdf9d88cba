#pragma once
// The seed's evaluation ("Bewertungs") functions (seed 000, ch. 4.2):
//   failed swing (eq. 4.9):      F = 1000 (1 + (2 pi - phi_x)), phi_x measured within the round
//   completed swing (eq. 4.10):  F = c_phi |phi'/omega - 1| + (180/pi)(c_alpha |alpha| + c_alpha' |alpha'|)
//                                    + c_friction int -M_R phi' dt + c_jerk 1/2 int alpha'''^2 dt
//                                    + c_moment 1/2 int M_alpha^2 dt
//   sequence of swings (eq. 4.14): F* = (sum_{n=1}^{R} F_n) 10^(20 - 3 R), R completed rounds.
// For R = 0 (the first round already failed) eq. 4.14 is undefined; we use F(4.9) 10^20 there,
// which ranks every such motion behind any motion completing a round.

#include "cyclopt/giant_swing/swing_simulation.hpp"

namespace cyclopt::giant_swing {

struct EvaluationWeights {
  double phi_rate = 100.0;   // c_phi'
  double alpha = 10.0;       // c_alpha (per degree)
  double alpha_rate = 1.0;   // c_alpha' (per degree/s)
  double friction = 0.0;     // c_Reib
  double jerk = 0.0;         // c_Jerk
  double moment = 0.0;       // c_Moment
};

// eq. 4.9; phi_in_round in [0, 2 pi).
double failed_swing_score(double phi_in_round);

// eq. 4.10 for one completed round ending at target rate omega.
double completed_swing_score(const EvaluationWeights& w, const RoundResult& round, double omega);

// eq. 4.10 / 4.9 for one requested round, eq. 4.14 for more.
double evaluation_score(const EvaluationWeights& w, const SimulationResult& simulation, int rounds_requested,
                        double omega);

}  // namespace cyclopt::giant_swing
