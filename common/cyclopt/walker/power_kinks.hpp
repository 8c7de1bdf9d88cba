#pragma once
// f_mech's kinked terms for a solver that models them (nlp/kinked_terms.hpp, issue 52). The seed's
// rule (5.102) integrates max(p, 0) of each joint power p = u q_dot over every trapezoid interval
// [t_i, t_i+1] with the zero crossing located on the linear interpolant (Fig. 5.3,
// positive_power.hpp): dt_i g(p_i, p_i+1) with g(a, b) = int_0^1 max((1 - s) a + s b, 0) ds, which
// is continuously differentiable except at a = b = 0. Near that kink
//   dt_i g(a, b) = dt_i / 2 (max(a, 0) + max(b, 0)) - (a remainder that vanishes with a and b),
// so each interval gives two terms, one per end, with weight dt_i / (2 m g L) in f_mech (the jump of
// d f_mech / d a across a = 0 at b = 0), each the other's partner; their slopes are those the
// gradient takes (the derivative of the interval's rule with respect to that end).

#include "cyclopt/nlp/kinked_terms.hpp"

#include <Eigen/Core>

namespace cyclopt::walker {

// power: joints x grid points (PeriodicGait::joint_power); power_jacobian: one row per sample j P + i
// (GaitDerivatives::joint_power); durations: t_i+1 - t_i (s, PeriodicGait::interval_duration);
// weight_step: m g L (N m), f_mech's denominator. None where weight_step <= 0 or a value is not finite.
nlp::KinkedTerms mechanical_power_kinks(const Eigen::MatrixXd& power, const Eigen::MatrixXd& power_jacobian,
                                        const Eigen::VectorXd& durations, double weight_step);

}  // namespace cyclopt::walker
