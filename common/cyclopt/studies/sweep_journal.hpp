#pragma once
// What a speed sweep has finished, so that a resumed sweep reuses it instead of solving it again
// (issue 19 item 5). The sweep is deterministic (multistart.hpp: results do not depend on the
// threads; a continuation run is sequential, and runs computed at once are numbered and taken in
// as one after the other, speed_sweep.hpp), so in every attempt its n-th multistart batch and its n-th
// continuation run are the same computation: they are keyed by sequence number. A run is recorded
// once it ended on its own (not stopped by the job); while it runs, where it stands after each
// converged point (continuation::RunState) is recorded too, so a run interrupted by a crash goes on
// from its last such point (issue 57) and repeats at most the one predictor-corrector step that was
// under way. Multistart solves are recorded one by one, so an interrupted batch repeats only the
// starts that had not finished.
// Empty functions: nothing is reused or recorded.

#include "cyclopt/continuation/solution_curve.hpp"
#include "cyclopt/nlp/multistart.hpp"
#include "cyclopt/nlp/solver_options.hpp"

#include <atomic>
#include <functional>
#include <optional>

namespace cyclopt::studies {

struct SweepJournal {
  std::function<std::optional<nlp::SolverSummary>(int batch, int start)> find_solve;
  std::function<void(int batch, int start, const nlp::SolverSummary& run)> record_solve;
  std::function<std::optional<continuation::ContinuationResult>(int run)> find_run;
  std::function<void(int run, const continuation::ContinuationResult& result)> record_run;
  std::function<std::optional<continuation::RunState>(int run)> find_run_state;
  std::function<void(int run, const continuation::RunState& state)> record_run_state;
};

// Makes a multistart take the solves of batch `batch` that the journal holds instead of solving
// them, and record the ones it finishes; *resumed (when given) counts the solves taken over (it is
// incremented from the multistart's worker threads). The journal must outlive the multistart.
inline void journal_multistart(nlp::MultistartOptions& options, const SweepJournal& journal, int batch,
                               std::atomic<int>* resumed = nullptr) {
  if (journal.find_solve)
    options.recorded_run = [&journal, resumed, batch](int i) {
      std::optional<nlp::SolverSummary> run = journal.find_solve(batch, i);
      if (run && resumed) ++*resumed;
      return run;
    };
  if (journal.record_solve)
    options.on_run_finished = [&journal, batch](int i, const nlp::SolverSummary& run) {
      journal.record_solve(batch, i, run);
    };
}

}  // namespace cyclopt::studies
