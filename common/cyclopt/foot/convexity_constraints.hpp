#pragma once
// Conditions that keep a parametrised foot convex, as data an optimiser can use.
//
// Linear part (seed 001, eq. 3.21 for HM, eq. 3.24 for HMT):  A p + b >= 0  componentwise.
// Every regularised transition has a positive curvature radius for k > 0 (appendix A), so the
// outline is convex as long as the generating polygon is. For HM eq. 3.21 ensures that; for HMT
// eq. 3.24 does not: a long, steep toe segment can lift the toe tip T so far above the ankle that
// the polygon A-H-M-T turns the wrong way at A. toe_convexity_margin() below is that missing
// (nonlinear) condition.

#include "cyclopt/foot/foot_parameters.hpp"

#include <Eigen/Core>

#include <cmath>
#include <string>
#include <vector>

namespace cyclopt::foot {

struct LinearInequalities {
  Eigen::MatrixXd A;               // rows x parameter count
  Eigen::VectorXd b;               // rows
  std::vector<std::string> names;  // one readable name per row, e.g. "l_HM - l_HA >= 0"
};

// Eq. (3.21) (HM) or (3.24) (HMT); empty for the point foot.
LinearInequalities convexity_constraints(FootModel model);

// HMT only: the cross product of the polygon edges T->A and A->H,
//   x_T h_F - z_T l_HA,  x_T = l_HM - l_HA + l_MT cos(gamma_F),  z_T = l_MT sin(gamma_F) - h_F,
// (T = (x_T, z_T) relative to the ankle). Positive exactly when the polygon is strictly convex at
// A, i.e. when the transition angles satisfy delta_4 < delta_1 + 2 pi (eq. 3.23). Templated so an
// optimiser can use it as a constraint with exact gradient.
template <class S>
S toe_convexity_margin(const FootParameters<S>& p) {
  using std::cos, std::sin;
  const S x_t = p[hmt::l_HM] - p[hmt::l_HA] + p[hmt::l_MT] * cos(p[hmt::gamma_F]);
  const S rise = p[hmt::l_MT] * sin(p[hmt::gamma_F]) - p[hmt::h_F];  // height of T above the ankle
  return x_t * p[hmt::h_F] - rise * p[hmt::l_HA];
}

}  // namespace cyclopt::foot
