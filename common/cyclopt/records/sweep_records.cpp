#include "cyclopt/records/sweep_records.hpp"

namespace cyclopt::records {

void to_json(nlohmann::json& j, const SweepBestRecord& b) {
  j = nlohmann::json::object();
  if (b.found_by) j["found_by"] = *b.found_by;
  if (b.reason) j["reason"] = *b.reason;
  j["sweep_seconds"] = b.sweep_seconds;
  j["curves"] = b.curves;
  j["closure"] = b.closure;
  j["closure_passes"] = b.closure_passes;
  if (b.seed_spread) j["seed_spread"] = *b.seed_spread;
  j["attempt"] = {{"multistart_solves", b.attempt.multistart_solves},
                  {"resumed_solves", b.attempt.resumed_solves},
                  {"computed_runs", b.attempt.computed_runs},
                  {"resumed_runs", b.attempt.resumed_runs}};
}

void from_json(const nlohmann::json& j, SweepBestRecord& b) {
  const std::string r = "values";
  b = SweepBestRecord{};
  b.found_by = optional_text(j, r, "found_by");
  b.reason = optional_text(j, r, "reason");
  b.sweep_seconds = number(j, r, "sweep_seconds");
  b.curves = integer(j, r, "curves");
  b.closure = text(j, r, "closure");
  b.closure_passes = integer(j, r, "closure_passes");
  b.seed_spread = optional_number(j, r, "seed_spread");
  const nlohmann::json& a = member(j, r, "attempt");
  const std::string ra = "values.attempt";
  b.attempt = {integer(a, ra, "multistart_solves"), integer(a, ra, "resumed_solves"), integer(a, ra, "computed_runs"),
               integer(a, ra, "resumed_runs")};
}

}  // namespace cyclopt::records
