#pragma once
// Where a speed sweep is and how long the rest should take, for a progress display (issue 17 item
// 3). The ETA is made of measured rates only: the wall seconds per multistart solve so far (with
// all worker threads) times the solves still to come at seed speeds, plus the wall seconds per
// grid speed reached by continuation so far times the speeds not reached yet (until a
// continuation run has reached a speed, one multistart solve per speed stands in for it). The
// recovery steps R1-R3 (speed_sweep.hpp) cannot be foreseen: in them the ETA counts the targets
// left at the mean time of the recoveries so far. Every phase's ETA adds one closure pass over the
// grid (at its measured seconds per speed, before it at half a solve per speed); in the closure,
// the rest of the pass. Whether further recoveries (dominance tests) or passes follow is not known
// ahead: the job's percentage then holds (service/progress_meter.hpp) instead of going back.

#include <limits>
#include <string>

namespace cyclopt::studies {

enum class SweepPhase { multistart, continuation, recovery, closure };
const char* to_string(SweepPhase phase);

struct SweepProgress {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  SweepPhase phase = SweepPhase::multistart;
  std::string detail;               // "at 1.3 m/s", "run 3 from 1.3 m/s upwards, curve 2"
  int phase_done = 0;               // multistart: solves finished in this batch; continuation: grid
  int phase_total = -1;             // speeds passed by this run (of phase_total); -1: unknown
  int speeds_reached = 0;           // grid speeds with a converged point on some curve
  int speeds_total = 0;
  double best_objective = kNaN;     // multistart: best converged objective of the batch so far;
                                    // else: the lowest converged objective at any grid speed
  double eta_seconds = kNaN;        // NaN until a rate has been measured
};

}  // namespace cyclopt::studies
