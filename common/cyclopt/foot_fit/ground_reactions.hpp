#pragma once
// The vertical ground-reaction force as the source of the rolling phase (seed 001 eq. 4.5: a
// foot rolls while it loads its force plate). A channel is one plate (or one foot, as OpenSim's
// processed files such as grf_walk.mot hold them) with its centre of pressure, or a single
// column: a CSV trial's "Fz" or a column the user names.

#include "cyclopt/foot_fit/marker_trial.hpp"
#include "cyclopt/foot_fit/opensim_storage_file.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace cyclopt::foot_fit {

struct ForceChannel {
  std::string source;                // file, for messages
  std::string name;                  // the plate's column prefix ("ground_force_r_") or the column
  int names_line = 0;                // file line naming the columns
  std::vector<double> time;          // s, increasing
  std::vector<double> vertical;      // N along the vertical axis (its magnitude counts); NaN: unloaded
  std::vector<Eigen::Vector3d> cop;  // m, in the marker files' axes; empty without centre of pressure

  // Linear interpolation at t (NaN read as 0); NaN outside the recorded times.
  double vertical_at(double t) const;
  // Centre of pressure at the sample nearest t (NaN without one).
  Eigen::Vector3d cop_at(double t) const;
};

// Every plate of an OpenSim ground-reaction table: a column triple PREFIXvx, PREFIXvy, PREFIXvz
// (force, N), with PREFIXpx, PREFIXpy, PREFIXpz (centre of pressure, m) when present; the
// component along `vertical_axis` (0, 1, 2 = x, y, z) is the vertical force. Throws
// TrialFormatError at the column names when the table has no such triple.
std::vector<ForceChannel> ground_reaction_channels(const StorageTable& table, int vertical_axis);

// One column of a table, or one analog column of a CSV trial, as the vertical force (no centre
// of pressure). Throws TrialFormatError at the column names, listing the columns, when it is missing.
ForceChannel force_column(const StorageTable& table, const std::string& name);
ForceChannel force_column(const MarkerTrial& trial, const std::string& name);

}  // namespace cyclopt::foot_fit
