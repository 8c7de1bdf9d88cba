#include "cyclopt/foot_fit/ground_reactions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cyclopt::foot_fit {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

double loaded(double v) { return std::isnan(v) ? 0.0 : v; }

}  // namespace

double ForceChannel::vertical_at(double t) const {
  if (time.empty() || t < time.front() || t > time.back()) return kNaN;
  const std::size_t b = static_cast<std::size_t>(std::lower_bound(time.begin(), time.end(), t) - time.begin());
  if (b == 0 || time[b] == t) return loaded(vertical[b]);
  const double s = (t - time[b - 1]) / (time[b] - time[b - 1]);
  return (1.0 - s) * loaded(vertical[b - 1]) + s * loaded(vertical[b]);
}

Eigen::Vector3d ForceChannel::cop_at(double t) const {
  if (cop.empty() || time.empty()) return Eigen::Vector3d::Constant(kNaN);
  std::size_t b = static_cast<std::size_t>(std::lower_bound(time.begin(), time.end(), t) - time.begin());
  if (b == time.size() || (b > 0 && t - time[b - 1] < time[b] - t)) --b;
  return cop[b];
}

std::vector<ForceChannel> ground_reaction_channels(const StorageTable& table, int vertical_axis) {
  static constexpr const char* kAxes[3] = {"x", "y", "z"};
  std::vector<ForceChannel> channels;
  for (const std::string& name : table.names) {
    if (name.size() < 3 || name.substr(name.size() - 3) != "_vx") continue;  // one triple per PREFIXvx
    const std::string prefix = name.substr(0, name.size() - 2);
    int force[3], cop[3];
    for (int a = 0; a < 3; ++a) {
      force[a] = table.column_index(prefix + "v" + kAxes[a]);
      cop[a] = table.column_index(prefix + "p" + kAxes[a]);
    }
    if (force[1] < 0 || force[2] < 0) continue;
    ForceChannel c;
    c.source = table.source;
    c.name = prefix;
    c.names_line = table.names_line;
    c.time = table.time;
    c.vertical = table.columns[force[vertical_axis]];
    if (cop[0] >= 0 && cop[1] >= 0 && cop[2] >= 0)
      for (int i = 0; i < table.rows(); ++i)
        c.cop.emplace_back(table.columns[cop[0]][i], table.columns[cop[1]][i], table.columns[cop[2]][i]);
    channels.push_back(std::move(c));
  }
  if (channels.empty())
    throw TrialFormatError(table.source, table.names_line, 0,
                           "no ground-reaction force (columns PREFIX_vx, PREFIX_vy, PREFIX_vz) among " + listed(table.names) +
                               "; name the vertical force with --force-column");
  return channels;
}

ForceChannel force_column(const StorageTable& table, const std::string& name) {
  const int c = table.column_index(name);
  if (c < 0)
    throw TrialFormatError(table.source, table.names_line, 0, "no column named '" + name + "' (columns: " + listed(table.names) + ")");
  return {table.source, name, table.names_line, table.time, table.columns[c], {}};
}

ForceChannel force_column(const MarkerTrial& trial, const std::string& name) {
  const int c = trial.analog_index(name);
  if (c < 0)
    throw TrialFormatError(trial.source, trial.marker_header_line, 0,
                           "no force column named '" + name + "' (analog columns: " +
                               (trial.analog_names.empty() ? std::string("none") : listed(trial.analog_names)) + ")");
  return {trial.source, name, trial.marker_header_line, trial.time, trial.analog[c], {}};
}

}  // namespace cyclopt::foot_fit
