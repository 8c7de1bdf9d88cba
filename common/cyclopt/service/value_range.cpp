#include "cyclopt/service/value_range.hpp"

#include "cyclopt/service/spec_fields.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cyclopt::service {

namespace {

constexpr double kOnGrid = 1e-9;

double parse_number(const std::string& text, const std::string& path, const std::string& syntax) {
  std::size_t used = 0;
  double x = 0.0;
  try {
    x = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(x))
    throw SpecError(path, "'" + text + "' is not a number; expected " + syntax);
  return x;
}

// lo + i step as the user reads it: rounded to 9 decimals below the step's leading digit, so that
// 0.3 + 3 * 0.1 = 0.6000000000000001 becomes 0.6, the double of "0.6". A grid point and the same
// value typed as a number are then the same problem, and the same stored speed (the walker's
// solves are chaotic in the last bits: a sweep over the unrounded grid found other local optima).
// n / 10^k with both exact is the double nearest the decimal n 10^-k.
double decimal_grid_value(double v, double step) {
  const int k = 9 - static_cast<int>(std::floor(std::log10(step)));
  if (k < 0 || k > 22) return v;          // 10^k exact in double for 0 <= k <= 22
  const double scale = std::pow(10.0, k);
  const double n = std::round(v * scale);
  return std::abs(n) < 0x1p53 ? n / scale : v;  // n exact
}

std::vector<double> parse_colon_range(const std::string& s, const std::string& path) {
  const std::string syntax = "\"lo:step:hi\" (e.g. \"0.3:0.1:2.3\"), a number or an array of numbers";
  std::vector<std::string> parts;
  std::stringstream ss(s);
  for (std::string part; std::getline(ss, part, ':');) parts.push_back(part);
  if (parts.size() != 3 || s.back() == ':') throw SpecError(path, "'" + s + "' must be " + syntax);
  const double lo = parse_number(parts[0], path, syntax);
  const double step = parse_number(parts[1], path, syntax);
  const double hi = parse_number(parts[2], path, syntax);
  if (hi < lo) throw SpecError(path, "'" + s + "': hi must be >= lo");
  if (!(step > 0.0)) throw SpecError(path, "'" + s + "': step must be > 0");
  // hi is on the grid when it lies within a relative kOnGrid of a step from a grid point; the
  // point count is computed in double, so it is finite or "more than" (never an overflowed cast).
  const double steps = (hi - lo) / step;
  if (!std::isfinite(steps) || steps + 1.0 > kMaxGridPoints) {
    std::ostringstream os;
    os << "'" << s << "' has ";
    if (std::isfinite(steps))
      os << std::floor(steps * (1.0 + kOnGrid) + kOnGrid) + 1.0;
    else
      os << "more than 1e308";
    os << " points; at most " << kMaxGridPoints << " are allowed";
    throw SpecError(path, os.str());
  }
  const int n = static_cast<int>(std::floor(steps * (1.0 + kOnGrid) + kOnGrid)) + 1;
  std::vector<double> out;
  for (int i = 0; i < n; ++i) out.push_back(std::min(decimal_grid_value(lo + step * i, step), hi));  // the last may round above hi
  return out;
}

}  // namespace

std::vector<double> parse_value_range(const nlohmann::json& v, const std::string& path, double lo, double hi) {
  std::vector<double> values;
  if (v.is_string()) {
    values = parse_colon_range(v.get<std::string>(), path);
  } else if (v.is_number()) {
    values.push_back(number_value(v, path, lo, hi));
  } else if (v.is_array()) {
    if (v.empty() || v.size() > kMaxGridPoints)
      throw SpecError(path, "must hold 1 to " + std::to_string(kMaxGridPoints) + " numbers, got " +
                                std::to_string(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i)
      values.push_back(number_value(v[i], path + "[" + std::to_string(i) + "]", lo, hi));
  } else {
    throw SpecError(path, "must be \"lo:step:hi\", a number or an array of numbers, got " + v.dump().substr(0, 80));
  }
  for (double x : values)
    if (x < lo - 1e-12 || x > hi + 1e-12) {
      std::ostringstream os;
      os << "values must lie in [" << lo << ", " << hi << "], got " << x;
      throw SpecError(path, os.str());
    }
  return values;
}

}  // namespace cyclopt::service
