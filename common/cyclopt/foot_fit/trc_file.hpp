#pragma once
// OpenSim / Motion Analysis track row column files (.trc): a tab-separated header of five lines
// (PathFileType; DataRate ... Units ...; their values; Frame#, Time and the marker names; X1 Y1
// Z1 ...) followed by one row per frame. Units "mm", "cm" or "m" as the header states. Header
// fields may be separated by runs of tabs; in the rows an empty or NaN field, or a marker at
// exactly (0, 0, 0), is a missing sample (marker_trial.hpp).

#include "cyclopt/foot_fit/marker_trial.hpp"

#include <iosfwd>
#include <string>

namespace cyclopt::foot_fit {

// Reads a .trc file; throws TrialFormatError naming file, line and column for a missing header
// field, an unknown unit, a row with more markers than the header, a non-numeric or infinite
// value, a frame count that disagrees with NumFrames, time that does not increase, or
// implausible units.
MarkerTrial read_trc(const std::string& path);
// Same from a stream; `source` names it in messages.
MarkerTrial read_trc(std::istream& in, const std::string& source);

// Writes `trial` in the given unit (positions converted from metres), with the data rate taken
// from the first time step. Analog columns are not part of the format and are not written.
void write_trc(const MarkerTrial& trial, const std::string& path, const std::string& units = "mm");
void write_trc(const MarkerTrial& trial, std::ostream& out, const std::string& units = "mm");

}  // namespace cyclopt::foot_fit
