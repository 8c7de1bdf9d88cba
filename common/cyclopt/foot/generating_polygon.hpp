#pragma once
// The convex polygon a foot model regularises (seed 001, Fig. 3.4), in the foot frame: origin at
// the ankle A, x forward, z up, sole flat. Vertices in order A, H, M (, T).

#include "cyclopt/foot/foot_parameters.hpp"

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace cyclopt::foot {

inline std::vector<Eigen::Vector2d> generating_polygon(FootModel model, const FootParameters<double>& p) {
  if (model == FootModel::point) return {Eigen::Vector2d::Zero()};
  std::vector<Eigen::Vector2d> v = {{0.0, 0.0}, {-p[hm::l_HA], -p[hm::h_F]}, {p[hm::l_HM] - p[hm::l_HA], -p[hm::h_F]}};
  if (model == FootModel::hmt)
    v.emplace_back(p[hmt::l_HM] - p[hmt::l_HA] + p[hmt::l_MT] * std::cos(p[hmt::gamma_F]),
                   -p[hmt::h_F] + p[hmt::l_MT] * std::sin(p[hmt::gamma_F]));
  return v;
}

}  // namespace cyclopt::foot
