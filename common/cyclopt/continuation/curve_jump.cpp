#include "cyclopt/continuation/curve_jump.hpp"

#include <algorithm>
#include <cmath>

namespace cyclopt::continuation {

JumpTest test_jump(const Eigen::VectorXd& x_old, const Eigen::VectorXd& x_new, double delta_p,
                   std::optional<double> previous_secant, const ContinuationOptions& o) {
  JumpTest t;
  const double distance = (x_new - x_old).norm();
  t.relative_distance = distance / std::max(1.0, x_old.norm());
  t.secant = distance / std::max(std::abs(delta_p), 1e-300);
  if (previous_secant)
    t.jump = t.relative_distance > o.jump_min_distance && t.secant > o.jump_slope_factor * *previous_secant;
  else
    t.jump = t.relative_distance > o.jump_first_distance;
  return t;
}

bool same_optimum_nearby(double p_a, const Eigen::VectorXd& x_a, double p_b, const Eigen::VectorXd& x_b,
                         const ContinuationOptions& o) {
  return std::abs(p_a - p_b) <= o.min_trust_region &&
         (x_a - x_b).norm() <= 0.25 * o.jump_min_distance * std::max(1.0, x_b.norm());
}

}  // namespace cyclopt::continuation
