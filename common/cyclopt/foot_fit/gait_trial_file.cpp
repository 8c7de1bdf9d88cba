#include "cyclopt/foot_fit/gait_trial_file.hpp"

#include "cyclopt/foot_fit/marker_file.hpp"
#include "cyclopt/foot_fit/opensim_storage_file.hpp"

namespace cyclopt::foot_fit {

GaitTrial read_gait_trial(const std::string& file, const GaitTrialOptions& o) {
  const MarkerTrial trial = read_marker_file(file, o.units);
  GaitTrial g{ankle_series(trial, o.ankle), {}};
  if (o.interval) {
    g.stances.push_back(interval_stance(g.ankle, o.interval->first, o.interval->second, o.stance));
  } else if (!o.forces_file.empty()) {
    const StorageTable table = read_opensim_storage(o.forces_file);
    if (o.force_column.empty())
      g.stances = force_stances(g.ankle, ground_reaction_channels(table, g.ankle.vertical_axis), true, o.stance);
    else
      g.stances = force_stances(g.ankle, {force_column(table, o.force_column)}, false, o.stance);
  } else if (trial.analog_index(o.force_column.empty() ? "Fz" : o.force_column) >= 0) {
    g.stances = force_stances(g.ankle, {force_column(trial, o.force_column.empty() ? "Fz" : o.force_column)}, false, o.stance);
  } else {
    if (!o.force_column.empty()) force_column(trial, o.force_column);  // throws, listing the columns
    g.stances = kinematic_stances(g.ankle, o.stance);
  }
  return g;
}

}  // namespace cyclopt::foot_fit
