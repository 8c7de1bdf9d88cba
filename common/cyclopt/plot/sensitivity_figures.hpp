#pragma once
// The sensitivities of an optimal gait (records/sensitivity_records.hpp, issue 15 item 6): the
// KKT sensitivities stored with an optimum as a report table, and a sensitivity job's comparison
// of them with the +-range continuation (seed 001 section 10.1) as a table and as the chart of
// Fig. 10.1: Delta f over the relative change of each parameter, the continuation's points as
// lines, the KKT tangent dashed in the same colour.

#include "cyclopt/plot/html_report.hpp"
#include "cyclopt/plot/walker_figures.hpp"
#include "cyclopt/records/sensitivity_records.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace cyclopt::plot {

struct SensitivityParameter {
  records::SensitivitySummaryRecord summary;
  std::vector<records::SensitivityStepRecord> steps;  // the continuation, ascending in p
};

// The summaries and continuation points of a sensitivity job document (`cyclopt export`), in
// parameter order. Throws std::invalid_argument for another task, records::RecordError for a
// point that does not follow the contract.
std::vector<SensitivityParameter> sensitivity_parameters(const nlohmann::json& document);

// The Fig. 10.1 chart; throws std::invalid_argument when no parameter has a continuation point.
Figure sensitivity_figure(const std::vector<SensitivityParameter>& parameters);

// The comparison table: parameter, value, KKT df/dp, relative, Delta f predicted and by
// continuation at -range / +range, verdict.
ReportTable sensitivity_comparison_table(const std::vector<SensitivityParameter>& parameters);

// The KKT sensitivities of one optimum: parameter, value, df/dp, relative, kink, where the active
// set changes on each side; and a sentence on the multipliers (or why there are no numbers).
ReportTable kkt_sensitivity_table(const records::KktSensitivitiesRecord& sensitivities);
std::string kkt_sensitivity_text(const records::KktSensitivitiesRecord& sensitivities);

}  // namespace cyclopt::plot
