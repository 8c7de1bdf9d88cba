#pragma once
// One foot's stances in a recording on disk: the marker file (.trc or CSV) and, optionally, its
// ground reactions (an OpenSim .mot / .sto), read and searched by the first rule that applies:
//   a hand-given interval           one stance, taken as given
//   a ground-reaction file          the plates' loaded runs near this foot (centre of pressure),
//                                   or every run of the column named by force_column
//   a CSV force column              its loaded runs (force_column, default "Fz")
//   else                            the kinematic rule (stances.hpp)

#include "cyclopt/foot_fit/stances.hpp"

#include <optional>
#include <string>
#include <utility>

namespace cyclopt::foot_fit {

struct GaitTrialOptions {
  AnkleSeriesOptions ankle;
  StanceOptions stance;
  std::optional<std::string> units;  // of CSV files without a "# units:" line
  std::optional<std::pair<double, double>> interval;  // s
  std::string forces_file;           // .mot / .sto; empty: none
  // The vertical force column: in the forces file (instead of every plate, assigned by centre
  // of pressure) or, without one, in the CSV trial. Empty: the plates, or a CSV's "Fz".
  std::string force_column;
};

// Throws TrialFormatError for malformed files (FILE:LINE:COLUMN) and for a named force column a
// file lacks, std::invalid_argument for bad options (an unknown file type, an empty interval).
GaitTrial read_gait_trial(const std::string& marker_file, const GaitTrialOptions& options = {});

}  // namespace cyclopt::foot_fit
