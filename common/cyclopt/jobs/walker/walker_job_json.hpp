#pragma once
// A parsed walker job (walker_job_spec.hpp) back in the spec's form with every default filled in:
// the walker kinds' part of the resolved spec (resolved_spec.hpp), the job's setup record
// (records/walker_setup_record.hpp) among it. The foot is written as its full
// parameters (a preset name becomes its parameter values), the start as its gait parameters x,
// the solver block with all five fields; "multistart" only for the kinds that draw random starts.
// Parsing the result again (parse_walker_job) gives the same WalkerJob.

#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/records/walker_setup_record.hpp"

#include <nlohmann/json.hpp>

namespace cyclopt::jobs {

// The foot, the model constants and the objective of the job.
records::WalkerSetupRecord walker_setup(const WalkerJob& job);

// `sweep`: write "speeds" (else "speed"); `random_starts`: write "multistart".
nlohmann::json walker_job_json(const WalkerJob& job, bool sweep, bool random_starts);

}  // namespace cyclopt::jobs
