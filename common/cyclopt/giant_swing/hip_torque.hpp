#pragma once
// Hip torque M_alpha(phi) of the seed's method (seed 000, ch. 3.2, eq. 3.13): linear interpolation
// of the values z_k at n = 2^j equidistant support points phi_k = 2 pi k / n on [0, 2 pi),
// continued 2 pi-periodically (the segment after phi_{n-1} closes onto z_0 at 2 pi), so a sequence
// of swings repeats the same profile (ch. 5.2). Refinement inserts a support point halfway
// between neighbours with the mean of their values: the function is unchanged (ch. 3.2).

#include "cyclopt/autodiff/scalar.hpp"
#include "cyclopt/giant_swing/model.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace cyclopt::giant_swing {

struct HipTorqueProfile {
  Eigen::VectorXd support_values;  // Nm, z_k at phi_k = 2 pi k / n
};

// M_alpha(phi); a Dual phi carries the slope of the interpolant.
template <class T>
T hip_torque(const HipTorqueProfile& profile, const T& phi) {
  const Eigen::Index n = profile.support_values.size();
  const T s = phi * (double(n) / kTwoPi);
  const double wraps = std::floor(ad::value(s) / double(n));
  const T s_mod = s - wraps * double(n);
  const double cell = std::floor(ad::value(s_mod));
  const Eigen::Index k = std::min<Eigen::Index>(std::max<Eigen::Index>(Eigen::Index(cell), 0), n - 1);
  const T w = s_mod - double(k);
  return (1.0 - w) * profile.support_values[k] + w * profile.support_values[(k + 1) % n];
}

// Twice the support points, same function (seed 000, ch. 3.2 and the multistage loop of ch. 4.3).
inline HipTorqueProfile refined(const HipTorqueProfile& profile) {
  const Eigen::Index n = profile.support_values.size();
  HipTorqueProfile out;
  out.support_values.resize(2 * n);
  for (Eigen::Index k = 0; k < n; ++k) {
    out.support_values[2 * k] = profile.support_values[k];
    out.support_values[2 * k + 1] = 0.5 * (profile.support_values[k] + profile.support_values[(k + 1) % n]);
  }
  return out;
}

}  // namespace cyclopt::giant_swing
