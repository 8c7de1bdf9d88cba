#pragma once
// The model parameter vector p_mod = [p_mech; p_foot; theta_F,0] of seed 001 eq. (5.91), so
// objective and constraints can be differentiated with respect to any of them (foot geometry
// co-optimisation, sensitivity studies of section 10.1).

#include "cyclopt/walker/walker_model.hpp"

#include <string>
#include <vector>

namespace cyclopt::walker {

// Size of p_mod: 15 segment parameters, the foot's parameters, theta_F,0 (point feet: 15).
int model_parameter_count(const WalkerModel<double>& m);
// Names: "l_T" ... "J_F", then the foot's ("h_F", "k_HM", ...), then "theta_F0".
std::vector<std::string> model_parameter_names(const WalkerModel<double>& m);
// Index of a named parameter; throws std::invalid_argument listing the valid names.
int model_parameter_index(const WalkerModel<double>& m, const std::string& name);

Eigen::VectorXd model_parameters(const WalkerModel<double>& m);

// The model with p_mod replaced (scalar type T, e.g. Dual to differentiate with respect to p).
template <class T>
WalkerModel<T> with_model_parameters(const WalkerModel<double>& base, const Eigen::Matrix<T, Eigen::Dynamic, 1>& p) {
  SegmentParameters<T> seg;
  for (int i = 0; i < segment_parameter_count; ++i) seg[i] = p(i);
  const int nf = static_cast<int>(base.foot_parameters.size());
  foot::FootParameters<T> fp(nf);
  for (int i = 0; i < nf; ++i) fp(i) = p(segment_parameter_count + i);
  const T zero_angle = base.has_feet() ? p(segment_parameter_count + nf) : T(base.foot_zero_angle);
  return make_walker_model<T>(seg, base.foot_model, fp, zero_angle, base.constants, base.foot.periodic_terms);
}

}  // namespace cyclopt::walker
