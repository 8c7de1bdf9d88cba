#pragma once
// One recorded trial of marker trajectories as a gait lab exports it (seed 001, section 4.1):
// sample times, named 3-D marker positions and, optionally, analog columns such as a force
// plate's vertical force. Positions are stored in metres whatever the file's unit.
//
// Real recordings have occluded markers. A marker sample is missing when a coordinate is blank
// or NaN, or when all three are exactly 0 (how several exporters, e.g. the one that wrote
// OpenSim's test_walking.trc, store a gap); it is kept as NaN. Whether a gap matters is decided
// where a marker is used (ankle_series.hpp), so a gap in a marker nobody fits never rejects a file.

#include <Eigen/Core>

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace cyclopt::foot_fit {

// A malformed marker file: what() reads "FILE:LINE:COLUMN: message" (1-based line; column is the
// 1-based field number of the delimited row, 0 when the whole line is at fault).
class TrialFormatError : public std::runtime_error {
 public:
  TrialFormatError(std::string file, int line, int column, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }

 private:
  std::string file_;
  int line_;
  int column_;
};

struct MarkerTrial {
  std::string source;                                  // file name, for messages
  std::string units;                                   // unit the file states ("mm", "cm", "m")
  std::vector<double> time;                            // s, strictly increasing
  std::vector<int> line_of_sample;                     // file line of each sample
  int marker_header_line = 0;                          // line that names the markers
  std::vector<std::string> marker_names;
  std::vector<std::vector<Eigen::Vector3d>> positions;  // [marker][sample], m; NaN where missing
  std::vector<std::string> analog_names;               // extra columns (CSV only), e.g. "Fz"
  std::vector<std::vector<double>> analog;             // [column][sample], in the file's unit (N)

  int samples() const { return static_cast<int>(time.size()); }
  bool present(int marker, int sample) const { return positions[marker][sample].allFinite(); }
  // Index of a marker; throws TrialFormatError at marker_header_line listing the markers.
  int marker_index(std::string_view name) const;
  // Index of an analog column or -1.
  int analog_index(std::string_view name) const;
};

// Metres per unit for "mm", "cm", "m"; throws std::invalid_argument for anything else.
double metres_per_unit(std::string_view unit);

// Parses one numeric field; throws TrialFormatError for empty fields, text, NaN and infinities
// (times, header values, analog channels).
double parse_number(std::string_view field, const std::string& file, int line, int column, std::string_view what);

// Parses one marker coordinate: blank and NaN fields give NaN (missing); text and infinities
// throw TrialFormatError.
double parse_coordinate(std::string_view field, const std::string& file, int line, int column, std::string_view what);

// A marker sample from its coordinates (in metres): NaN in every coordinate when one is missing
// or all three are exactly 0.
Eigen::Vector3d marker_sample(const Eigen::Vector3d& coordinates);

// Rejects coordinates that cannot be a walking trial in the stated unit: any |value| above 50 m
// (millimetres labelled as metres) or all present values below 5 mm in magnitude (metres labelled
// as millimetres). The message names the line and column of the offending value.
void check_plausible_units(const MarkerTrial& trial, const std::vector<std::vector<int>>& column_of_coordinate);

// Rejects time that does not increase strictly, naming the line and time column.
void check_monotone_time(const MarkerTrial& trial, int time_column);

}  // namespace cyclopt::foot_fit
