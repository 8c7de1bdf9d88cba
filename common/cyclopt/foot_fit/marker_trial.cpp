#include "cyclopt/foot_fit/marker_trial.hpp"

#include <charconv>
#include <cmath>
#include <limits>

namespace cyclopt::foot_fit {

TrialFormatError::TrialFormatError(std::string file, int line, int column, const std::string& message)
    : std::runtime_error(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message),
      file_(std::move(file)),
      line_(line),
      column_(column) {}

int MarkerTrial::marker_index(std::string_view name) const {
  for (std::size_t m = 0; m < marker_names.size(); ++m)
    if (marker_names[m] == name) return static_cast<int>(m);
  std::string known;
  for (const std::string& n : marker_names) known += (known.empty() ? "" : ", ") + n;
  throw TrialFormatError(source, marker_header_line, 0,
                         "no marker named '" + std::string(name) + "' (markers in the file: " + known + ")");
}

int MarkerTrial::analog_index(std::string_view name) const {
  for (std::size_t c = 0; c < analog_names.size(); ++c)
    if (analog_names[c] == name) return static_cast<int>(c);
  return -1;
}

double metres_per_unit(std::string_view unit) {
  if (unit == "mm") return 1e-3;
  if (unit == "cm") return 1e-2;
  if (unit == "m") return 1.0;
  throw std::invalid_argument("unit '" + std::string(unit) + "' is not one of mm, cm, m");
}

namespace {

std::string_view trimmed_field(std::string_view field) {
  while (!field.empty() && (field.front() == ' ' || field.front() == '\r')) field.remove_prefix(1);
  while (!field.empty() && (field.back() == ' ' || field.back() == '\r')) field.remove_suffix(1);
  return field;
}

bool is_nan_text(std::string_view f) {
  if (!f.empty() && (f.front() == '-' || f.front() == '+')) f.remove_prefix(1);
  return f.size() == 3 && (f[0] == 'n' || f[0] == 'N') && (f[1] == 'a' || f[1] == 'A') && (f[2] == 'n' || f[2] == 'N');
}

}  // namespace

double parse_coordinate(std::string_view field, const std::string& file, int line, int column, std::string_view what) {
  field = trimmed_field(field);
  if (field.empty() || is_nan_text(field)) return std::numeric_limits<double>::quiet_NaN();
  return parse_number(field, file, line, column, what);
}

Eigen::Vector3d marker_sample(const Eigen::Vector3d& c) {
  if (!c.allFinite() || (c.array() == 0.0).all()) return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  return c;
}

double parse_number(std::string_view field, const std::string& file, int line, int column, std::string_view what) {
  field = trimmed_field(field);
  if (field.empty())
    throw TrialFormatError(file, line, column, std::string(what) + ": empty field (value missing)");
  double v = 0.0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
  if (ec != std::errc() || end != field.data() + field.size())
    throw TrialFormatError(file, line, column, std::string(what) + ": '" + std::string(field) + "' is not a number");
  if (!std::isfinite(v))
    throw TrialFormatError(file, line, column, std::string(what) + ": '" + std::string(field) + "' is not finite (NaN or inf)");
  return v;
}

void check_plausible_units(const MarkerTrial& t, const std::vector<std::vector<int>>& column_of_coordinate) {
  constexpr double kLargest = 50.0;   // m: no gait lab is larger
  constexpr double kSmallest = 5e-3;  // m: a walking ankle moves more than this
  double largest = 0.0;
  bool any = false;
  for (std::size_t m = 0; m < t.positions.size(); ++m)
    for (int i = 0; i < t.samples(); ++i)
      for (int a = 0; a < 3; ++a) {
        const double v = std::abs(t.positions[m][i][a]);
        if (std::isnan(v)) continue;
        if (v > kLargest)
          throw TrialFormatError(t.source, t.line_of_sample[i], column_of_coordinate[m][a],
                                 "coordinate " + std::to_string(v) + " m exceeds " + std::to_string(int(kLargest)) +
                                     " m: the stated unit '" + t.units + "' is wrong (values in mm?)");
        largest = std::max(largest, v);
        any = true;
      }
  if (any && largest < kSmallest)
    throw TrialFormatError(t.source, t.line_of_sample.front(), column_of_coordinate.front().front(),
                           "all coordinates are below 5 mm in magnitude: the stated unit '" + t.units +
                               "' is wrong (values in m?)");
}

void check_monotone_time(const MarkerTrial& t, int time_column) {
  for (int i = 1; i < t.samples(); ++i)
    if (!(t.time[i] > t.time[i - 1]))
      throw TrialFormatError(t.source, t.line_of_sample[i], time_column,
                             "time " + std::to_string(t.time[i]) + " s does not increase (previous sample " +
                                 std::to_string(t.time[i - 1]) + " s)");
}

}  // namespace cyclopt::foot_fit
