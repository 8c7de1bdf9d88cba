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

}  // namespace cyclopt::continuation
