#pragma once
// What a running speed sweep (speed_sweep.hpp) tells the code that runs it, and what it may take
// over from an earlier attempt: an interface beside the plain-data SpeedSweepOptions, the way Ceres
// keeps its callbacks out of Solver::Options. Every method's default observes nothing.

#include "cyclopt/continuation/continuation_solver.hpp"
#include "cyclopt/studies/sweep_journal.hpp"
#include "cyclopt/studies/sweep_progress.hpp"

#include <utility>

namespace cyclopt::studies {

class SpeedSweepObserver {
 public:
  virtual ~SpeedSweepObserver() = default;
  // Every new point (never the repeated first point of a run that starts on a point already
  // reported); returning false stops the sweep (its result then holds what was done).
  virtual bool on_point(const continuation::CurvePoint&) { return true; }
  // When a phase begins, after every multistart solve and at every converged grid point
  // (sweep_progress.hpp); from the sweep's thread or, one call at a time, from multistart workers
  // and the thread of a downward run (speed_sweep.hpp).
  virtual void on_progress(const SweepProgress&) {}
  // Resume: what an earlier attempt finished and where this one records its own
  // (sweep_journal.hpp); asked once when the sweep begins. Empty: nothing is reused or recorded.
  virtual SweepJournal journal() { return {}; }
};

// An observer of the points only (an empty f sees none and never stops the sweep).
class PointObserver final : public SpeedSweepObserver {
 public:
  explicit PointObserver(continuation::PointCallback f) : f_(std::move(f)) {}
  bool on_point(const continuation::CurvePoint& p) override { return !f_ || f_(p); }

 private:
  continuation::PointCallback f_;
};

}  // namespace cyclopt::studies
