#pragma once
// One recorded trial of marker trajectories as a gait lab exports it (seed 001, section 4.1):
// sample times, named 3-D marker positions and, optionally, analog columns such as a force
// plate's vertical force. Positions are stored in metres whatever the file's unit.

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
  std::vector<std::vector<Eigen::Vector3d>> positions;  // [marker][sample], m
  std::vector<std::string> analog_names;               // extra columns (CSV only), e.g. "Fz"
  std::vector<std::vector<double>> analog;             // [column][sample], in the file's unit (N)

  int samples() const { return static_cast<int>(time.size()); }
  // Index of a marker; throws TrialFormatError at marker_header_line listing the markers.
  int marker_index(std::string_view name) const;
  // Index of an analog column or -1.
  int analog_index(std::string_view name) const;
};

// Metres per unit for "mm", "cm", "m"; throws std::invalid_argument for anything else.
double metres_per_unit(std::string_view unit);

// Parses one numeric field; throws TrialFormatError for empty fields (occluded markers), text,
// NaN and infinities.
double parse_number(std::string_view field, const std::string& file, int line, int column, std::string_view what);

// Rejects coordinates that cannot be a walking trial in the stated unit: any |value| above 50 m
// (millimetres labelled as metres) or all values below 5 mm in magnitude (metres labelled as
// millimetres). The message names the line and column of the offending value.
void check_plausible_units(const MarkerTrial& trial, const std::vector<std::vector<int>>& column_of_coordinate);

// Rejects time that does not increase strictly, naming the line and time column.
void check_monotone_time(const MarkerTrial& trial, int time_column);

}  // namespace cyclopt::foot_fit
