#pragma once
// A speed sweep's journal (studies/sweep_journal.hpp) kept in the job's checkpoints
// (JobContext::store_checkpoint), so a sweep interrupted by a crash, a restart or a lost Slurm unit
// resumes with the solves and continuation runs it had finished (issue 19 item 5). Keys:
//   "solve/<batch>/<start>"  one multistart solve (an nlp::SolverSummary)
//   "run/<n>"                one continuation run (a continuation::ContinuationResult)
//   "run_state/<n>"          where run n stood at its last converged point (continuation::RunState),
//                            replaced at each; a resumed run goes on from there
// The walker multistart job uses the same journal for its single batch (batch 0). A job of several
// sweeps (foot_design_kind.hpp) gives each its own prefix: "<prefix>solve/...", "<prefix>run/...".
// Values are JSON with every field, doubles in round-trip precision, so a replayed sweep takes the
// same decisions as the uninterrupted one; a solver summary is written as the result contract's
// records::SolverRecord with its multipliers, a curve point's step as records::ContinuationStepRecord.
// An unreadable checkpoint is treated as absent.

#include "cyclopt/service/job_context.hpp"
#include "cyclopt/studies/foot_comparison.hpp"
#include "cyclopt/studies/sweep_journal.hpp"

#include <nlohmann/json.hpp>

namespace cyclopt::jobs {

// Reads the stored checkpoints once; the journal writes new ones through ctx.
studies::SweepJournal sweep_journal(service::JobContext& ctx, const std::string& prefix = "");

nlohmann::json summary_to_json(const nlp::SolverSummary& s);
nlp::SolverSummary summary_from_json(const nlohmann::json& j);  // throws records::RecordError
nlohmann::json run_to_json(const continuation::ContinuationResult& r);
continuation::ContinuationResult run_from_json(const nlohmann::json& j);
nlohmann::json run_state_to_json(const continuation::RunState& s);
continuation::RunState run_state_from_json(const nlohmann::json& j);

// One foot's finished sweep reduced to its best point per speed (studies::FootSweepSummary): the
// result a comparison's or a design's work unit leaves for its job (foot/foot_comparison_kind.cpp,
// foot/foot_design_kind.cpp), read back to combine the units and by a resumed job instead of sweeping
// the foot again. Mean, saving and common speeds are not kept: summarise_feet computes them.
nlohmann::json foot_sweep_to_json(const studies::FootSweepSummary& s);
// Throws (records::RecordError, nlohmann::json::exception, std::out_of_range) on a malformed value.
studies::FootSweepSummary foot_sweep_from_json(const nlohmann::json& j);

}  // namespace cyclopt::jobs
