#include "cyclopt/foot_fit/opensim_storage_file.hpp"

#include "cyclopt/foot_fit/delimited_line.hpp"
#include "cyclopt/foot_fit/marker_trial.hpp"

#include <cctype>
#include <fstream>
#include <istream>
#include <limits>

namespace cyclopt::foot_fit {
namespace {

// The fields of a line separated by runs of tabs and spaces.
std::vector<std::string_view> whitespace_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

int StorageTable::column_index(std::string_view name) const {
  for (std::size_t c = 0; c < names.size(); ++c)
    if (names[c] == name) return static_cast<int>(c);
  return -1;
}

StorageTable read_opensim_storage(std::istream& in, const std::string& source) {
  StorageTable t;
  t.source = source;
  std::string line;
  int line_no = 0, declared_columns = -1, columns_line = 0;
  bool header_ended = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::vector<std::string_view> words = whitespace_fields(line);
    const std::string l = words.empty() ? std::string() : lower(words.front());
    if (l == "endheader") {
      header_ended = true;
      break;
    }
    if (l.rfind("ncolumns=", 0) == 0) {
      declared_columns = static_cast<int>(parse_number(words.front().substr(9), source, line_no, 1, "nColumns"));
      columns_line = line_no;
    }
  }
  if (!header_ended)
    throw TrialFormatError(source, line_no, 0, "no line 'endheader': not an OpenSim storage file (.mot, .sto)");
  while (std::getline(in, line)) {
    ++line_no;
    if (!is_blank(line)) break;
  }
  const std::vector<std::string_view> names = whitespace_fields(line);
  t.names_line = line_no;
  if (names.empty() || lower(names[0]) != "time")
    throw TrialFormatError(source, line_no, 1, "the line after 'endheader' names the columns, starting with 'time'");
  if (declared_columns >= 0 && declared_columns != static_cast<int>(names.size()))
    throw TrialFormatError(source, columns_line, 1,
                           "nColumns says " + std::to_string(declared_columns) + " but line " + std::to_string(line_no) +
                               " names " + std::to_string(names.size()));
  for (std::size_t c = 1; c < names.size(); ++c) t.names.emplace_back(names[c]);
  t.columns.assign(t.names.size(), {});
  while (std::getline(in, line)) {
    ++line_no;
    if (is_blank(line)) continue;
    const std::vector<std::string_view> f = whitespace_fields(line);
    if (f.size() != names.size())
      throw TrialFormatError(source, line_no, static_cast<int>(std::min(f.size(), names.size())) + 1,
                             "row has " + std::to_string(f.size()) + " fields, line " + std::to_string(t.names_line) +
                                 " names " + std::to_string(names.size()) + " columns");
    t.time.push_back(parse_number(f[0], source, line_no, 1, "time"));
    t.line_of_row.push_back(line_no);
    for (std::size_t c = 1; c < f.size(); ++c)
      t.columns[c - 1].push_back(parse_coordinate(f[c], source, line_no, static_cast<int>(c) + 1, t.names[c - 1]));
  }
  for (int i = 1; i < t.rows(); ++i)
    if (!(t.time[i] > t.time[i - 1]))
      throw TrialFormatError(source, t.line_of_row[i], 1,
                             "time " + std::to_string(t.time[i]) + " s does not increase (previous row " +
                                 std::to_string(t.time[i - 1]) + " s)");
  return t;
}

StorageTable read_opensim_storage(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw TrialFormatError(path, 0, 0, "cannot open the file");
  return read_opensim_storage(in, path);
}

}  // namespace cyclopt::foot_fit
