#pragma once
// The nonsmooth (Clarke) stationarity test of issue 52 item 2 and its multipliers. At x, with the
// kinked terms near their kink K (kinked_terms.hpp), the Clarke generalised gradients of the
// Lagrangian are
//
//   r = grad f + sum_{s in K} (sigma_s - a_s) grad p_s + J_eq' y_eq + J_A' y_A + nu,
//   sigma_s in [0, w_s],  y_A >= 0 on the active inequalities,  nu <= 0 (>= 0) at active lower
//   (upper) bounds,  y_eq free
//
// (a_s the slope grad f took at sample s). x is a nonsmooth KKT point when some r vanishes (within
// TolOpt) and x is feasible. The multipliers minimise |r|_2 (bound-constrained least squares,
// qp/bounded_least_squares.hpp): the signed form of the least-squares multipliers (6.26), and with
// K empty exactly the smooth test with the signs enforced. The residual reported is |r|_inf of that
// minimiser, an upper bound of the least attainable |r|_inf.
//
// The box [0, w_s] per sample is the model of f_mech's kinks. For the seed's trapezoid rule
// with zero crossing (Fig. 5.3) it contains the true Clarke subgradients of two consecutive vanishing
// samples (a convex lens inside the box of the interval's two half weights): the test is the one of
// the issue and of bench/results/speed_sweep_bench.txt block "12-06 03:05" item 4, with the interval
// rule's partner condition (a sample counts only where its interval partner vanishes too).

#include "cyclopt/nlp/active_set_projections.hpp"
#include "cyclopt/nlp/kinked_terms.hpp"
#include "cyclopt/nlp/problem.hpp"

#include <Eigen/Core>

namespace cyclopt::nlp {

struct ClarkeMultipliers {
  Eigen::VectorXd equality;    // y_eq, size m_eq
  Eigen::VectorXd inequality;  // y_in, size m_in, 0 off the active set
  Eigen::VectorXd bound;       // nu, size n, 0 at inactive bounds (sign convention of SolverSummary)
  NearKinks kinks;             // K
  Eigen::VectorXd kink;        // sigma per sample of K
  double residual = 0.0;       // |r|_inf
};

// Needs an evaluation with derivatives at x. Bounds in `active.bounds` are at their lower (upper)
// bound when within bound_tolerance of it (nu's sign then follows; both: nu free).
ClarkeMultipliers clarke_multipliers(const Evaluation& e, const ActiveConstraints& active, const NearKinks& kinks,
                                     const Eigen::VectorXd& x, const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                     double bound_tolerance);

}  // namespace cyclopt::nlp
