#include "cyclopt/foot_fit/trc_file.hpp"

#include "cyclopt/foot_fit/delimited_line.hpp"

#include <cstdio>
#include <fstream>
#include <istream>
#include <limits>
#include <ostream>

namespace cyclopt::foot_fit {
namespace {

std::string trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.remove_suffix(1);
  return std::string(s);
}

}  // namespace

MarkerTrial read_trc(std::istream& in, const std::string& source) {
  MarkerTrial t;
  t.source = source;
  std::string header[5];
  for (int l = 0; l < 5; ++l)
    if (!std::getline(in, header[l]))
      throw TrialFormatError(source, l + 1, 0, "the file ends inside the five-line .trc header");
  if (header[0].rfind("PathFileType", 0) != 0)
    throw TrialFormatError(source, 1, 1, "a .trc file starts with 'PathFileType'");
  // Keys and values are matched by position among the non-empty fields: some exporters pad
  // them with extra tabs, differently on the two lines.
  const std::vector<std::string_view> keys = split_on_runs(header[1], '\t');
  const std::vector<std::string_view> values = split_on_runs(header[2], '\t');
  auto header_value = [&](std::string_view key) -> std::pair<std::string, int> {
    for (std::size_t c = 0; c < keys.size(); ++c)
      if (trimmed(keys[c]) == key) {
        if (c >= values.size()) throw TrialFormatError(source, 3, int(c) + 1, "no value for header field " + std::string(key));
        return {trimmed(values[c]), int(c) + 1};
      }
    throw TrialFormatError(source, 2, 0, "header field " + std::string(key) + " missing");
  };
  const auto [units, units_column] = header_value("Units");
  double scale = 0.0;
  try {
    scale = metres_per_unit(units);
  } catch (const std::invalid_argument& e) {
    throw TrialFormatError(source, 3, units_column, std::string("Units: ") + e.what());
  }
  t.units = units;
  const auto [frames_text, frames_column] = header_value("NumFrames");
  const double declared_frames = parse_number(frames_text, source, 3, frames_column, "NumFrames");
  const auto [markers_text, markers_column] = header_value("NumMarkers");
  const double declared_markers = parse_number(markers_text, source, 3, markers_column, "NumMarkers");

  t.marker_header_line = 4;
  std::vector<std::string> names;  // the non-blank fields: Frame#, Time, then one name per marker
  for (std::string_view f : split_on_runs(header[3], '\t'))
    if (!is_blank(f)) names.push_back(trimmed(f));
  if (names.size() < 2 || names[0] != "Frame#" || names[1] != "Time")
    throw TrialFormatError(source, 4, 1, "the fourth header line starts with 'Frame#' and 'Time'");
  t.marker_names.assign(names.begin() + 2, names.end());
  if (static_cast<double>(t.marker_names.size()) != declared_markers)
    throw TrialFormatError(source, 3, markers_column,
                           "NumMarkers says " + markers_text + " but line 4 names " + std::to_string(t.marker_names.size()));
  const int markers = static_cast<int>(t.marker_names.size());
  t.positions.assign(markers, {});
  std::vector<std::vector<int>> column_of(markers, std::vector<int>(3));
  for (int m = 0; m < markers; ++m)
    for (int a = 0; a < 3; ++a) column_of[m][a] = 3 + 3 * m + a;

  std::string line;
  int line_no = 5;
  static constexpr const char* kAxis[3] = {"X", "Y", "Z"};
  while (std::getline(in, line)) {
    ++line_no;
    if (is_blank(line)) continue;
    // Data rows keep one tab per field: an empty field is a missing coordinate. Exporters drop
    // the empty fields of occluded markers at the end of a row, so a short row is read as such.
    const std::vector<std::string_view> f = split_fields(line, '\t');
    if (f.size() < 2) throw TrialFormatError(source, line_no, int(f.size()) + 1, "row has no Time field");
    for (std::size_t c = 2 + 3 * markers; c < f.size(); ++c)
      if (!is_blank(f[c]))
        throw TrialFormatError(source, line_no, int(c) + 1,
                               "row has " + std::to_string(f.size()) + " fields, the header names " + std::to_string(markers) +
                                   " markers (" + std::to_string(2 + 3 * markers) + " fields)");
    parse_number(f[0], source, line_no, 1, "Frame#");
    t.time.push_back(parse_number(f[1], source, line_no, 2, "Time"));
    t.line_of_sample.push_back(line_no);
    for (int m = 0; m < markers; ++m) {
      Eigen::Vector3d p;
      for (int a = 0; a < 3; ++a) {
        const std::size_t c = 2 + 3 * m + a;
        p[a] = c < f.size() ? scale * parse_coordinate(f[c], source, line_no, column_of[m][a], t.marker_names[m] + " " + kAxis[a])
                            : std::numeric_limits<double>::quiet_NaN();
      }
      t.positions[m].push_back(marker_sample(p));
    }
  }
  if (static_cast<double>(t.samples()) != declared_frames)
    throw TrialFormatError(source, 3, frames_column,
                           "NumFrames says " + frames_text + " but the file has " + std::to_string(t.samples()) + " rows");
  check_monotone_time(t, 2);
  check_plausible_units(t, column_of);
  return t;
}

MarkerTrial read_trc(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw TrialFormatError(path, 0, 0, "cannot open the file");
  return read_trc(in, path);
}

void write_trc(const MarkerTrial& t, std::ostream& out, const std::string& units) {
  const double per_unit = 1.0 / metres_per_unit(units);
  const double rate = t.samples() > 1 ? 1.0 / (t.time[1] - t.time[0]) : 0.0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", rate);
  const std::string n = std::to_string(t.samples()), m = std::to_string(t.marker_names.size());
  out << "PathFileType\t4\t(X/Y/Z)\t" << t.source << "\n";
  out << "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n";
  out << buf << "\t" << buf << "\t" << n << "\t" << m << "\t" << units << "\t" << buf << "\t1\t" << n << "\n";
  out << "Frame#\tTime";
  for (const std::string& name : t.marker_names) out << "\t" << name << "\t\t";
  out << "\n\t";
  for (std::size_t k = 1; k <= t.marker_names.size(); ++k) out << "\tX" << k << "\tY" << k << "\tZ" << k;
  out << "\n\n";
  for (int i = 0; i < t.samples(); ++i) {
    std::snprintf(buf, sizeof buf, "%d\t%.6f", i + 1, t.time[i]);
    out << buf;
    for (const auto& marker : t.positions)
      for (int a = 0; a < 3; ++a) {
        std::snprintf(buf, sizeof buf, "\t%.8f", marker[i][a] * per_unit);
        out << (marker[i].allFinite() ? buf : "\t");  // a missing sample as empty fields
      }
    out << "\n";
  }
}

void write_trc(const MarkerTrial& t, const std::string& path, const std::string& units) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write the file");
  write_trc(t, out, units);
}

}  // namespace cyclopt::foot_fit
