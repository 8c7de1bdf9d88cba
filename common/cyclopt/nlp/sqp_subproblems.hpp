#pragma once
// The quadratic and linear subproblems of the seed's SQP in the step d from x (seed 001,
// section 6.2.1). Bounds lower <= x + d <= upper are kept as hard constraints in all three
// (x itself is inside them, so d = 0 satisfies them and the relaxations stay feasible).

#include "cyclopt/nlp/problem.hpp"
#include "cyclopt/qp/active_set_solver.hpp"
#include "cyclopt/qp/positive_part_qp.hpp"
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

// Issue 52 (not in the seed): (6.7) with the kinked terms near their kink K (kinked_terms.hpp)
// modelled as what they are - l1 terms, as (6.13) treats violated constraints:
//
//   min (grad f - sum_K a_s grad p_s)' d + 1/2 d'Wd + sum_K w_s max(p_s + grad p_s' d, 0)  s.t. (6.7)'s rows,
//
// i.e. with the elastic variables t_s >= p_s + grad p_s' d, t_s >= 0 at cost w_s t_s, whose
// multipliers sigma_s in [0, w_s] say which samples do positive work. The samples outside K keep their
// smooth branch (their slopes stay in the gradient). Solved by qp/positive_part_qp.hpp (W positive definite).
struct KinkedSubproblem {
  qp::QuadraticProgram qp;       // (6.7) with the gradient of the smooth remainder
  qp::PositivePartTerms terms;   // a = grad p_s, b = -p_s, weights w_s
};

KinkedSubproblem kinked_sqp_subproblem(const LinearisationPoint& at, const Eigen::MatrixXd& W, const NearKinks& kinks);

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
