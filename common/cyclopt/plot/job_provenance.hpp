#pragma once
// Where a report's numbers come from (issue 54), as its first, boxed section: the program version
// and build (instruction-set level and flags) the job ran on, its random seeds, when it was
// submitted, started and finished, and the spec as resolved (every default filled in, what the
// job ran) and as submitted; read from the job row of a document `cyclopt export` writes.

#include "cyclopt/plot/html_report.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace cyclopt::plot {

// Unix seconds as ISO 8601 UTC ("2026-12-06T16:38:56Z"); "-" for a value that is not a number.
std::string iso_utc(const nlohmann::json& unix_seconds);

ReportSection provenance_section(const nlohmann::json& document);

}  // namespace cyclopt::plot
