#pragma once
// Bounds on a foot's dimensions for geometry optimisation (seed 001, section 10.2, eq. 10.1):
//
//   0 <= [l_HM,max - l_HM,  h_F,max - h_F,  h_F - l_MT,  k_HM,max - k_HM,  k_MT,max - k_MT]
//
// with the seed's values l_HM,max = 400 mm, h_F,max = 100 mm, k_HM,max = k_MT,max = 0.5 as
// defaults. They keep the optimiser from growing the foot without limit (section 10.2); the toe
// row limits the whole sole length. HM feet have no l_MT or k_MT, so their rows are omitted. The
// rows are linear, A p + b >= 0, in the layout of foot_parameters.hpp, like the convexity
// conditions (3.21 / 3.24) they are used with.

#include "cyclopt/foot/convexity_constraints.hpp"

#include <string>
#include <vector>

namespace cyclopt::foot {

struct DesignBounds {
  double l_HM_max = 0.400;         // m
  double h_F_max = 0.100;          // m
  bool toe_within_height = true;   // l_MT <= h_F (HMT only)
  double k_HM_max = 0.5;           // rad
  double k_MT_max = 0.5;           // rad (HMT only)
};

// One numeric bound: its field name, the foot parameter it limits and the range a bound may take
// (the parameter's own admissible range, parameter_layout()).
struct DesignBoundField {
  std::string name;       // "l_HM_max", ...
  std::string parameter;  // "l_HM", ...
  double min;
  double max;
  double DesignBounds::*value;
};
// The numeric fields that apply to a model (HM: l_HM_max, h_F_max, k_HM_max).
std::vector<DesignBoundField> design_bound_fields(FootModel model);

// Rows of eq. (10.1) for the model; empty for the point foot.
LinearInequalities design_constraints(FootModel model, const DesignBounds& bounds);

// The rows of eq. (10.1) a foot violates (by more than `tolerance`), by name; empty if admissible.
std::vector<std::string> violated_design_bounds(FootModel model, const FootParameters<double>& p,
                                                const DesignBounds& bounds, double tolerance = 0.0);

// The foot moved onto the bounds it violates, only in the parameters listed as movable (a
// start foot's free parameters): l_HM, h_F, k_HM, k_MT clipped to their maxima, then l_MT to
// h_F. The seed's start foot P2 (h_F = 106.5 mm, l_MT = 112.4 mm) lies outside its own bounds.
FootParameters<double> project_into_design_bounds(FootModel model, FootParameters<double> p, const DesignBounds& bounds,
                                                  const std::vector<std::string>& movable);

}  // namespace cyclopt::foot
