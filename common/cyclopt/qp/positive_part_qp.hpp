#pragma once
// A strictly convex QP with positive-part (l1) terms,
//
//   min_x 1/2 x'Hx + g'x + sum_k w_k max(a_k'x - b_k, 0)
//   s.t.  A_eq x = b_eq,  A_in x <= b_in,  lower <= x <= upper,   H positive definite,
//
// the SQP subproblem of issue 52 (nlp/sqp_subproblems.hpp): the elastic form with t_k >= a_k'x - b_k,
// t_k >= 0 and cost w_k t_k, whose multiplier of t_k's row is sigma_k in [0, w_k]. Solved through
// its dual, which has only simple bounds: with v = (sigma, y_in, y_eq) for the rows M = [a; A_in
// (and bounds); A_eq] with right-hand sides r, x(v) = -H^-1 (g + M'v) and
//
//   min_v 1/2 (g + M'v)' H^-1 (g + M'v) + r'v   s.t.  0 <= sigma <= w,  y_in >= 0,  y_eq free,
//
// whose gradient is r - M x(v): a variable at its lower bound may leave it when its row is violated
// at x(v), sigma_k at w_k when its piece is negative there - the Goldfarb-Idnani idea (only violated
// rows enter), with the box on sigma that makes the many pieces of a held joint, vanishing together
// on a few directions, a degenerate but well-posed problem. The free set is solved as in BVLS
// (bounded_least_squares.hpp): its stationary point (minimum norm where free rows are dependent),
// taken as far as the box allows; a direction of no curvature along which the dual decreases
// without bound proves the constraints inconsistent (infeasible QP, then the SQP's l1 relaxation).

#include "cyclopt/qp/active_set_solver.hpp"
#include "cyclopt/qp/quadratic_program.hpp"

#include <Eigen/Core>

namespace cyclopt::qp {

struct PositivePartTerms {
  Eigen::MatrixXd matrix;   // rows a_k' (K x n)
  Eigen::VectorXd rhs;      // b_k
  Eigen::VectorXd weights;  // w_k > 0
};

struct PositivePartQpSolution {
  QpSolution qp;            // x, the constraints' multipliers (sign convention of QpSolution), working set
  Eigen::VectorXd sigma;    // per term, in [0, w_k]
};

// Where the dual starts, e.g. at the previous SQP iteration's solution: the constraints taken as
// active (their multipliers free) and sigma per term (at 0 or w_k it starts at that bound, between
// them free; empty: all 0). Any start is valid - the dual has simple bounds only - and a good one
// saves most of the iterations.
struct PositivePartQpStart {
  WorkingSet active;
  Eigen::VectorXd sigma;
};

// Throws std::invalid_argument for inconsistent sizes, H not positive definite (is_strictly_convex
// with options.curvature_tolerance), weights <= 0 or a start.sigma of another size. iterations
// counts changes of the free set.
PositivePartQpSolution solve_positive_part_qp(const QuadraticProgram& qp, const PositivePartTerms& terms,
                                              const ActiveSetOptions& options = {}, const PositivePartQpStart& start = {});

}  // namespace cyclopt::qp
