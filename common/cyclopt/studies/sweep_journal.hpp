#pragma once
// What a speed sweep has finished, so that a resumed sweep reuses it instead of solving it again
// (issue 19 item 5). The sweep is deterministic (multistart.hpp: results do not depend on the
// threads; continuation is sequential), so in every attempt its n-th multistart batch and its n-th
// continuation run are the same computation: they are keyed by sequence number. A run is recorded
// once it ended on its own (not stopped by the job); a run interrupted by a crash is computed again
// from its start, and its points already stored keep their keys. Multistart solves are recorded
// one by one, so an interrupted batch repeats only the starts that had not finished.
// Empty functions: nothing is reused or recorded.

#include "cyclopt/continuation/solution_curve.hpp"
#include "cyclopt/nlp/solver_options.hpp"

#include <functional>
#include <optional>

namespace cyclopt::studies {

struct SweepJournal {
  std::function<std::optional<nlp::SolverSummary>(int batch, int start)> find_solve;
  std::function<void(int batch, int start, const nlp::SolverSummary& run)> record_solve;
  std::function<std::optional<continuation::ContinuationResult>(int run)> find_run;
  std::function<void(int run, const continuation::ContinuationResult& result)> record_run;
};

}  // namespace cyclopt::studies
