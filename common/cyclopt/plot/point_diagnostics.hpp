#pragma once
// How every stored point of a job was obtained (issue 54), one table row per stored point of every
// curve, numbered as `cyclopt query` numbers them: the solver and how it ended, its iterations,
// KKT (stationarity) error, constraint violation and time, which step found the point or where
// its solve started, the stored status and whether it counts as converged. A point that did not
// converge is marked (ReportTable::failed). Read through the result contract (records/): a walker
// point's solve and continuation step, a sweep best row's found_by; rows of other records show
// what the solutions row itself holds.

#include "cyclopt/plot/html_report.hpp"

#include <nlohmann/json.hpp>

namespace cyclopt::plot {

// Rows in the document's order (curve, then point); throws records::RecordError for a walker
// point that does not follow the contract.
ReportTable point_diagnostics_table(const nlohmann::json& document);

// The table under a heading, with a line saying how many points did not converge.
ReportSection point_diagnostics_section(const nlohmann::json& document);

}  // namespace cyclopt::plot
