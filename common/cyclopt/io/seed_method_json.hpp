#pragma once
// The seed's method's results (giant_swing/seed_optimiser.hpp) as JSON, in the units of the seed's
// tables (seed 000 ch. 5: phi'/omega, deg, deg/s, J, rad^2/s^5, Nm^2 s).

#include "cyclopt/giant_swing/seed_optimiser.hpp"
#include "cyclopt/records/giant_swing_records.hpp"

#include <nlohmann/json_fwd.hpp>

namespace cyclopt::io {

// One round of a swing simulation, in the units of the seed's tables.
records::SwingRoundRecord round_record(const giant_swing::RoundResult& round, double omega);
nlohmann::json to_json(const giant_swing::RoundResult& round, double omega);

// The whole result: the task, the end-of-round values, the integrals, the support values, the
// stages, counts and times.
nlohmann::json to_json(const giant_swing::SeedMethodResult& result, const giant_swing::TaskSpec& spec);

}  // namespace cyclopt::io
