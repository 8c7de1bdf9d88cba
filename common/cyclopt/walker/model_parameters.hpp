#pragma once
// The model parameter vector p_mod = [p_mech; p_foot; theta_F,0 (; rho)] of seed 001 eq. (5.91),
// so objective and constraints can be differentiated with respect to any of them (foot geometry
// co-optimisation, sensitivity studies of section 10.1). A scene whose foot has a density
// (section 10.2) has rho ("density") as its last entry; m_F, r_F, J_F and (unless fixed by the
// foot spec) theta_F,0 are then functions of the foot parameters and rho (appendix E): their
// entries hold the derived values and are ignored on input.

#include "cyclopt/walker/walker_model.hpp"

#include <string>
#include <utility>
#include <vector>

namespace cyclopt::walker {

// Size of p_mod: 15 segment parameters, the foot's parameters, theta_F,0, rho (point feet: 15).
int model_parameter_count(const WalkerModel<double>& m);
// Names: "l_T" ... "J_F", then the foot's ("h_F", "k_HM", ...), then "theta_F0", then "density".
std::vector<std::string> model_parameter_names(const WalkerModel<double>& m);
// Index of a named parameter; throws std::invalid_argument listing the valid names.
int model_parameter_index(const WalkerModel<double>& m, const std::string& name);
// True for the entries the density derives from the geometry (m_F, r_F, J_F, theta_F,0); they
// cannot be optimised or continued on their own.
bool follows_foot_geometry(const WalkerModel<double>& m, int index);
// Index of rho in p_mod, or -1 without a density.
int density_index(const WalkerModel<double>& m);
// Admissible range [min, max] of p_mod entry `index`: the segment table, the foot layout,
// theta_F,0 in [0, 2 pi], the foot spec's density range.
std::pair<double, double> model_parameter_range(const WalkerModel<double>& m, int index);

Eigen::VectorXd model_parameters(const WalkerModel<double>& m);

// The model with p_mod replaced (scalar type T, e.g. Dual to differentiate with respect to p).
// With a density the mass properties are recomputed from the new foot parameters and rho.
template <class T>
WalkerModel<T> with_model_parameters(const WalkerModel<double>& base, const Eigen::Matrix<T, Eigen::Dynamic, 1>& p) {
  SegmentParameters<T> seg;
  for (int i = 0; i < segment_parameter_count; ++i) seg[i] = p(i);
  const int nf = static_cast<int>(base.foot_parameters.size());
  foot::FootParameters<T> fp(nf);
  for (int i = 0; i < nf; ++i) fp(i) = p(segment_parameter_count + i);
  const T zero_angle = base.has_feet() ? p(segment_parameter_count + nf) : T(base.foot_zero_angle);
  FootDensity<T> density;
  density.zero_angle_from_geometry = base.foot_density.zero_angle_from_geometry;
  if (base.foot_density.active()) density.rho = p(density_index(base));
  return make_walker_model<T>(seg, base.foot_model, fp, zero_angle, base.constants, base.foot.periodic_terms, density);
}

}  // namespace cyclopt::walker
