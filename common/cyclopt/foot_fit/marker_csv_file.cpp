#include "cyclopt/foot_fit/marker_csv_file.hpp"

#include "cyclopt/foot_fit/delimited_line.hpp"

#include <array>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <istream>
#include <map>
#include <ostream>

namespace cyclopt::foot_fit {
namespace {

std::string trimmed(std::string_view s) {
  const std::size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return {};
  const std::size_t e = s.find_last_not_of(" \t\r");
  return std::string(s.substr(b, e - b + 1));
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// "LMAL_x" -> ("LMAL", 0); -1 when the name is not a marker coordinate.
std::pair<std::string, int> marker_axis(const std::string& column) {
  if (column.size() < 3 || column[column.size() - 2] != '_') return {column, -1};
  const char a = static_cast<char>(std::tolower(static_cast<unsigned char>(column.back())));
  const int axis = a == 'x' ? 0 : a == 'y' ? 1 : a == 'z' ? 2 : -1;
  return {column.substr(0, column.size() - 2), axis};
}

}  // namespace

MarkerTrial read_marker_csv(std::istream& in, const std::string& source, const std::optional<std::string>& units) {
  MarkerTrial t;
  t.source = source;
  std::string line;
  int line_no = 0;
  std::optional<std::string> file_units;
  int units_line = 0;
  std::vector<std::string_view> header;
  std::string header_text;
  while (std::getline(in, line)) {
    ++line_no;
    if (is_blank(line)) continue;
    const std::string l = trimmed(line);
    if (l.front() == '#') {
      const std::string body = lower(trimmed(std::string_view(l).substr(1)));
      if (body.rfind("units:", 0) == 0) {
        file_units = trimmed(std::string_view(l).substr(l.find(':') + 1));
        units_line = line_no;
      }
      continue;
    }
    header_text = line;
    header = split_fields(header_text, ',');
    break;
  }
  if (header.empty()) throw TrialFormatError(source, line_no, 0, "no header line (time,NAME_x,NAME_y,NAME_z,...)");
  t.marker_header_line = line_no;
  if (file_units && units && *file_units != *units)
    throw TrialFormatError(source, units_line, 0, "the file states units '" + *file_units + "' but '" + *units + "' was given");
  if (!file_units && !units)
    throw TrialFormatError(source, 1, 0, "units not stated: add a line '# units: mm' (or cm, m) or give the units");
  t.units = file_units ? *file_units : *units;
  double scale = 0.0;
  try {
    scale = metres_per_unit(t.units);
  } catch (const std::invalid_argument& e) {
    throw TrialFormatError(source, file_units ? units_line : 1, 0, e.what());
  }
  if (lower(trimmed(header[0])) != "time")
    throw TrialFormatError(source, t.marker_header_line, 1, "the first column is 'time' (s), found '" + trimmed(header[0]) + "'");

  // Columns of each marker's three axes, in order of first appearance.
  std::vector<std::array<int, 3>> columns;  // 1-based, 0 = missing
  std::map<std::string, int> marker_of;
  std::vector<int> analog_columns;
  for (std::size_t c = 1; c < header.size(); ++c) {
    const std::string name = trimmed(header[c]);
    const auto [marker, axis] = marker_axis(name);
    if (axis < 0) {
      t.analog_names.push_back(name);
      analog_columns.push_back(int(c) + 1);
      continue;
    }
    auto [it, inserted] = marker_of.try_emplace(marker, int(columns.size()));
    if (inserted) {
      t.marker_names.push_back(marker);
      columns.push_back({0, 0, 0});
    }
    if (columns[it->second][axis] != 0)
      throw TrialFormatError(source, t.marker_header_line, int(c) + 1, "column '" + name + "' appears twice");
    columns[it->second][axis] = int(c) + 1;
  }
  for (std::size_t m = 0; m < columns.size(); ++m)
    for (int a = 0; a < 3; ++a)
      if (columns[m][a] == 0)
        throw TrialFormatError(source, t.marker_header_line, 0,
                               "marker '" + t.marker_names[m] + "' has no column " + t.marker_names[m] + "_" + "xyz"[a]);
  t.positions.assign(columns.size(), {});
  t.analog.assign(analog_columns.size(), {});
  while (std::getline(in, line)) {
    ++line_no;
    if (is_blank(line) || trimmed(line).front() == '#') continue;
    const std::vector<std::string_view> f = split_fields(line, ',');
    if (f.size() != header.size())
      throw TrialFormatError(source, line_no, int(std::min(f.size(), header.size())) + 1,
                             "row has " + std::to_string(f.size()) + " fields, the header " + std::to_string(header.size()));
    t.time.push_back(parse_number(f[0], source, line_no, 1, "time"));
    t.line_of_sample.push_back(line_no);
    for (std::size_t m = 0; m < columns.size(); ++m) {
      Eigen::Vector3d p;
      for (int a = 0; a < 3; ++a)
        p[a] = scale * parse_coordinate(f[columns[m][a] - 1], source, line_no, columns[m][a], trimmed(header[columns[m][a] - 1]));
      t.positions[m].push_back(marker_sample(p));
    }
    for (std::size_t c = 0; c < analog_columns.size(); ++c)
      t.analog[c].push_back(parse_number(f[analog_columns[c] - 1], source, line_no, analog_columns[c], t.analog_names[c]));
  }
  std::vector<std::vector<int>> column_of;
  for (const auto& c : columns) column_of.push_back({c[0], c[1], c[2]});
  check_monotone_time(t, 1);
  check_plausible_units(t, column_of);
  return t;
}

MarkerTrial read_marker_csv(const std::string& path, const std::optional<std::string>& units) {
  std::ifstream in(path);
  if (!in) throw TrialFormatError(path, 0, 0, "cannot open the file");
  return read_marker_csv(in, path, units);
}

void write_marker_csv(const MarkerTrial& t, std::ostream& out, const std::string& units) {
  const double per_unit = 1.0 / metres_per_unit(units);
  out << "# units: " << units << "\n# source: " << t.source << "\ntime";
  for (const std::string& n : t.marker_names) out << "," << n << "_x," << n << "_y," << n << "_z";
  for (const std::string& n : t.analog_names) out << "," << n;
  out << "\n";
  char buf[64];
  for (int i = 0; i < t.samples(); ++i) {
    std::snprintf(buf, sizeof buf, "%.6f", t.time[i]);
    out << buf;
    for (const auto& marker : t.positions)
      for (int a = 0; a < 3; ++a) {
        std::snprintf(buf, sizeof buf, ",%.8f", marker[i][a] * per_unit);
        out << (marker[i].allFinite() ? buf : ",");  // a missing sample as empty fields
      }
    for (const auto& channel : t.analog) {
      std::snprintf(buf, sizeof buf, ",%.6g", channel[i]);
      out << buf;
    }
    out << "\n";
  }
}

void write_marker_csv(const MarkerTrial& t, const std::string& path, const std::string& units) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write the file");
  write_marker_csv(t, out, units);
}

}  // namespace cyclopt::foot_fit
