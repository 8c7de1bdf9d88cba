#pragma once
// Marker trajectories as plain CSV, one file per trial:
//
//   # units: mm
//   time,LMAL_x,LMAL_y,LMAL_z,MMAL_x,MMAL_y,MMAL_z,Fz
//   0.000,102.1,-35.0,84.2,101.7,35.2,84.0,0
//
// Lines starting with '#' are comments; "# units: mm|cm|m" states the unit of the marker columns.
// The first column is the time in s; columns NAME_x, NAME_y, NAME_z (all three) form a marker;
// any other column is an analog channel kept under its name (e.g. a force plate's Fz in N).

#include "cyclopt/foot_fit/marker_trial.hpp"

#include <iosfwd>
#include <optional>
#include <string>

namespace cyclopt::foot_fit {

// Reads a CSV trial. `units` states the unit when the file has no "# units:" line; a file whose
// own statement disagrees with `units` is rejected. Throws TrialFormatError naming file, line
// and column (missing unit, a marker without all three axes, a short row, a non-numeric value,
// an empty / NaN time or analog value, time that does not increase, implausible units). Empty or
// NaN marker coordinates are missing samples (marker_trial.hpp).
MarkerTrial read_marker_csv(const std::string& path, const std::optional<std::string>& units = std::nullopt);
MarkerTrial read_marker_csv(std::istream& in, const std::string& source,
                            const std::optional<std::string>& units = std::nullopt);

// Writes `trial` (positions converted from metres to `units`, analog columns as they are).
void write_marker_csv(const MarkerTrial& trial, const std::string& path, const std::string& units = "mm");
void write_marker_csv(const MarkerTrial& trial, std::ostream& out, const std::string& units = "mm");

}  // namespace cyclopt::foot_fit
