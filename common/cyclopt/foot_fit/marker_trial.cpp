#include "cyclopt/foot_fit/marker_trial.hpp"

#include <charconv>
#include <cmath>

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

double parse_number(std::string_view field, const std::string& file, int line, int column, std::string_view what) {
  while (!field.empty() && (field.front() == ' ' || field.front() == '\r')) field.remove_prefix(1);
  while (!field.empty() && (field.back() == ' ' || field.back() == '\r')) field.remove_suffix(1);
  if (field.empty())
    throw TrialFormatError(file, line, column, std::string(what) + ": empty field (marker occluded or value missing)");
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
  for (std::size_t m = 0; m < t.positions.size(); ++m)
    for (int i = 0; i < t.samples(); ++i)
      for (int a = 0; a < 3; ++a) {
        const double v = std::abs(t.positions[m][i][a]);
        if (v > kLargest)
          throw TrialFormatError(t.source, t.line_of_sample[i], column_of_coordinate[m][a],
                                 "coordinate " + std::to_string(v) + " m exceeds " + std::to_string(int(kLargest)) +
                                     " m: the stated unit '" + t.units + "' is wrong (values in mm?)");
        largest = std::max(largest, v);
      }
  if (!t.positions.empty() && t.samples() > 0 && largest < kSmallest)
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
