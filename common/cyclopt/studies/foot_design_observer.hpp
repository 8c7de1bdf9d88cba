#pragma once
// What a running foot design study (foot_design.hpp) tells the code that runs it, and the journals
// it may resume from: an interface beside the plain-data FootDesignOptions, the way Ceres keeps its
// callbacks out of Solver::Options. Every method's default observes nothing. The study runs on two
// threads (step 3) but calls its observer one call at a time, as from one thread.

#include "cyclopt/studies/foot_comparison.hpp"
#include "cyclopt/studies/sweep_journal.hpp"
#include "cyclopt/studies/sweep_progress.hpp"
#include "cyclopt/walker/walker_model.hpp"

#include <string>

namespace cyclopt::studies {

struct DensityDesign;

// The phases of one density, in order (FootDesignObserver::on_density).
enum class DesignPhase { multistart, free_foot, high_sweep, low_sweep };

class FootDesignObserver {
 public:
  virtual ~FootDesignObserver() = default;
  // A step begins: "references: start foot and point feet", "rho 10: design multistart", ...
  // Returning false stops the study (its result holds what was done).
  virtual bool on_step(const std::string& /*step*/) { return true; }
  // Results as they are found, for a caller that stores them; returning false stops the study.
  // Each reference sweep (part: its journal's name, foot_design.hpp; the walker swept).
  virtual bool on_reference(const std::string& /*part*/, const walker::WalkerModel<double>& /*model*/,
                            const FootSweepSummary& /*sweep*/) {
    return true;
  }
  // A density's result so far after each of its phases ends (high_sweep and low_sweep both after
  // the later of the two sweeps).
  virtual bool on_density(const DensityDesign& /*so_far*/, DesignPhase /*finished*/) { return true; }
  // After every run of a design multistart (nlp::MultistartOptions::on_progress: runs taken so far
  // of `starts`, best objective).
  virtual void on_multistart_progress(double /*density*/, int /*runs_done*/, double /*best*/) {}
  // The progress of each fixed-foot sweep (SpeedSweepObserver::on_progress) but the design's own,
  // which runs beside step 2 and reports none.
  virtual void on_sweep_progress(const SweepProgress& /*progress*/) {}
  // The journal of a part of the study (names in foot_design.hpp); empty: nothing is reused or
  // recorded.
  virtual SweepJournal journal(const std::string& /*part*/) { return {}; }
};

}  // namespace cyclopt::studies
