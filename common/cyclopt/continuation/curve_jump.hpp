#pragma once
// Detection of a jump to another solution curve (seed 001, section 8.2, Fig. 8.4): when the
// followed optimum stops existing, the corrector converges to a different local optimum. On a
// curve, x moves with p at a bounded rate; a jump shows as a secant |x_{k+1} - x_k| / |Delta p|
// far above the previous one, over a distance that is not small.
#include "cyclopt/continuation/continuation_options.hpp"
#include <Eigen/Core>
#include <optional>

namespace cyclopt::continuation {

struct JumpTest {
  bool jump = false;
  double relative_distance = 0.0;  // |x_new - x_old|_2 / max(1, |x_old|_2)
  double secant = 0.0;             // |x_new - x_old|_2 / |Delta p|
};

// previous_secant: of the last step on the same curve, if there was one.
JumpTest test_jump(const Eigen::VectorXd& x_old, const Eigen::VectorXd& x_new, double delta_p,
                   std::optional<double> previous_secant, const ContinuationOptions& options);

// Whether converged points of two curves are one optimum: within the smallest step
// (Delta_min) in p, and closer than a quarter of the distance that makes a jump
// (|x_a - x_b|_2 / max(1, |x_b|_2) <= jump_min_distance / 4). Two curves a jump apart are farther
// apart than that; a curve retraced from a nearby start comes closer (the speed sweep's jumps,
// studies/speed_sweep.cpp: landings 1e-4..3e-3 in max norm from points found before).
bool same_optimum_nearby(double p_a, const Eigen::VectorXd& x_a, double p_b, const Eigen::VectorXd& x_b,
                         const ContinuationOptions& options);

}  // namespace cyclopt::continuation
