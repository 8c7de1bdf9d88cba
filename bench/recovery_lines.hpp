#pragma once
// One line per recovery attempt of a speed sweep (studies/speed_sweep.hpp: R1-R3 at an unreached
// or possibly dominated speed), for the sweep benchmarks: where a sweep's recovery time goes.

#include "cyclopt/studies/speed_sweep.hpp"

#include <cstdio>
#include <vector>

namespace cyclopt::bench {

inline void print_recoveries(const std::vector<studies::RecoveryAttempt>& attempts, const char* indent = "") {
  for (const studies::RecoveryAttempt& a : attempts) {
    std::printf("%srecovery at %.1f m/s (%s): %d solves, %.1f s, ", indent, a.speed, a.trigger.c_str(), a.solves, a.seconds);
    if (a.found)
      std::printf("%s found f_mech %.6f\n", studies::to_string(a.step), a.objective);
    else
      std::printf("nothing better\n");
  }
}

}  // namespace cyclopt::bench
