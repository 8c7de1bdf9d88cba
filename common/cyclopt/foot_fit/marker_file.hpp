#pragma once
// A trial file of either format the fit reads, chosen by its extension: .trc (trc_file.hpp) or
// .csv (marker_csv_file.hpp).

#include "cyclopt/foot_fit/marker_trial.hpp"

#include <optional>
#include <string>

namespace cyclopt::foot_fit {

// Throws TrialFormatError (file, line, column) for a malformed file and std::invalid_argument
// for another extension. `units`: the unit of CSV files without a "# units:" line.
MarkerTrial read_marker_file(const std::string& path, const std::optional<std::string>& units = std::nullopt);

}  // namespace cyclopt::foot_fit
