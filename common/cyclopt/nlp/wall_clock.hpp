#pragma once
// Wall time of solves and studies (SolverOptions::max_wall_seconds, the seconds every summary
// reports): a steady clock and the seconds since a point of it.
#include <chrono>

namespace cyclopt::nlp {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace cyclopt::nlp
