#pragma once
// OpenSim storage files (.mot, .sto), the format of OpenSim's ground-reaction files such as
// grf_walk.mot: header lines up to one reading "endheader" (a name, version=, nRows=,
// nColumns=, inDegrees=, ...), a line of column names starting with "time", then one row of
// numbers per time. Fields are separated by tabs or spaces.

#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace cyclopt::foot_fit {

struct StorageTable {
  std::string source;
  int names_line = 0;               // file line of the column names
  std::vector<std::string> names;   // the columns after "time"
  std::vector<double> time;         // s, strictly increasing
  std::vector<int> line_of_row;
  std::vector<std::vector<double>> columns;  // [column][row]; NaN where the file says NaN

  int rows() const { return static_cast<int>(time.size()); }
  // Index of a column or -1.
  int column_index(std::string_view name) const;
};

// Throws TrialFormatError naming file, line and column: no "endheader", nColumns that disagrees
// with the names, a first column other than time, a row with another number of fields, text
// where a number belongs, time that does not increase.
StorageTable read_opensim_storage(const std::string& path);
StorageTable read_opensim_storage(std::istream& in, const std::string& source);

}  // namespace cyclopt::foot_fit
