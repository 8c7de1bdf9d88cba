#pragma once
// The quadratic and linear subproblems of the seed's SQP in the step d from x (seed 001,
// section 6.2.1). Bounds lower <= x + d <= upper are kept as hard constraints in all three
// (x itself is inside them, so d = 0 satisfies them and the relaxations stay feasible).

#include "cyclopt/nlp/problem.hpp"
#include "cyclopt/qp/active_set_solver.hpp"
#include "cyclopt/qp/quadratic_program.hpp"
#include "cyclopt/qp/screened_solve.hpp"

#include <Eigen/Core>

namespace cyclopt::nlp {

// The point the subproblems linearise at: evaluation with derivatives, x and the simple bounds.
struct LinearisationPoint {
  const Evaluation& evaluation;
  const Eigen::VectorXd& x;
  const Eigen::VectorXd& lower;
  const Eigen::VectorXd& upper;
};

// eq. (6.7): min grad f d + 1/2 d'Wd s.t. J_g d + c_g = 0, J_u d + c_u <= 0.
qp::QuadraticProgram sqp_subproblem(const LinearisationPoint& at, const Eigen::MatrixXd& W);

// The l1 programs (6.13)/(6.14) are solved exactly but with fewer variables: slacks t start on
// the inequalities violated at x only and are added to a hard row only when its multiplier
// exceeds the slack weight (then, and only then, the full program would violate it). With all
// m_in slacks up front the dense QP would have n + 2 m_eq + m_in variables (~2000 for the walker),
// O((n + m_in)^3) per active-set iteration. Solution x = (d, r, s, t); working-set inequality
// indices name constraints as in (6.7); the warm start may be any earlier working set.

// eq. (6.13), variables (d, r, s, t): min grad f d + 1/2 d'Wd + mu (sum(r + s) + sum t)
// s.t. J_g d + c_g = r - s, J_u d + c_u <= t, r, s, t >= 0. Semidefinite (no curvature in r, s, t).
qp::QpSolution solve_l1_relaxed_subproblem(const LinearisationPoint& at, const Eigen::MatrixXd& W, double mu,
                                          const qp::ActiveSetOptions& options, const qp::ScreeningOptions& screening,
                                          const qp::WorkingSet& warm_start);

// eq. (6.14), variables (d, r, s, t): min sum(r + s) + sum t s.t. the constraints of (6.13) and
// |d|_inf <= trust_radius. An LP (H = 0).
qp::QpSolution solve_l1_feasibility_lp(const LinearisationPoint& at, double trust_radius, const qp::ActiveSetOptions& options,
                                      const qp::ScreeningOptions& screening);

}  // namespace cyclopt::nlp
