#include "cyclopt/walker/power_kinks.hpp"

#include "cyclopt/autodiff/dual.hpp"
#include "cyclopt/walker/positive_power.hpp"

namespace cyclopt::walker {

nlp::KinkedTerms mechanical_power_kinks(const Eigen::MatrixXd& power, const Eigen::MatrixXd& power_jacobian,
                                        const Eigen::VectorXd& durations, double weight_step) {
  using D = ad::Dual<2>;
  const Eigen::Index joints = power.rows(), points = power.cols();
  nlp::KinkedTerms k;
  // No kinks to declare where f_mech's denominator is not positive (a gait stepping backwards: the
  // positive parts enter with negative weights, concave) or the powers' derivatives are not finite.
  if (!(weight_step > 0.0) || !power.allFinite() || !power_jacobian.allFinite() || !durations.allFinite()) return k;
  k.values = power.transpose().reshaped();  // sample j P + i
  k.jacobian = power_jacobian;
  k.terms.reserve(static_cast<size_t>(2 * joints * (points - 1)));
  for (Eigen::Index j = 0; j < joints; ++j)
    for (Eigen::Index i = 0; i + 1 < points; ++i) {
      const double dt = durations[i];
      const D rule = positive_part_trapezoid(D::variable(power(j, i), 0), D::variable(power(j, i + 1), 1), D(dt));
      const int left = static_cast<int>(j * points + i), right = left + 1;
      const double weight = 0.5 * dt / weight_step;
      k.terms.push_back({left, right, weight, rule.d[0] / weight_step});
      k.terms.push_back({right, left, weight, rule.d[1] / weight_step});
    }
  return k;
}

}  // namespace cyclopt::walker
