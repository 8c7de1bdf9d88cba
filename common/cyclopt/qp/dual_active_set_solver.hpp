#pragma once
// Dual active-set method of Goldfarb & Idnani ("A numerically stable dual method for solving
// strictly convex quadratic programs", Math. Programming 27, 1983) for the QPs of
// quadratic_program.hpp with a positive DEFINITE Hessian - the QP (6.7) of the seed's SQP, whose
// damped-BFGS matrix W_k (6.20)-(6.25) is positive definite by construction.
//
// It starts at the unconstrained minimiser -H^-1 g and adds, one at a time, the most violated
// constraint, dropping active ones whose multiplier would turn negative; every iterate is dual
// feasible, so the first primal feasible iterate is the optimum. Only violated rows ever enter
// the computation, which suits the walker's QPs (2003 inequality rows, a few dozen active)
// without screening, and the method cannot stall on degenerate vertices the way a primal
// active-set method can: each full step strictly increases the dual objective. A constraint that
// cannot be satisfied proves the QP infeasible (then the SQP turns to its l1 relaxation (6.13)).
//
// The working set is refactorised from scratch after each change (H = L L', L^-1 N = Q R,
// Goldfarb-Idnani's J = L^-T Q): O(n^2 q) per iteration, which for the tens of variables of the
// SQP subproblems costs less than keeping Givens updates exact.

#include "cyclopt/qp/active_set_solver.hpp"
#include "cyclopt/qp/quadratic_program.hpp"

namespace cyclopt::qp {

// True if H is symmetric positive definite enough for solve_dual_active_set: its Cholesky factor
// exists with every pivot^2 >= curvature_tolerance * max(1, max|H_ii|).
bool is_strictly_convex(const Eigen::MatrixXd& hessian, double curvature_tolerance);

// Same contract as solve_active_set (statuses, multiplier signs, working set); H must be positive
// definite (std::invalid_argument otherwise). phase_one_iterations is always 0.
QpSolution solve_dual_active_set(const QuadraticProgram& qp, const ActiveSetOptions& options = {});

}  // namespace cyclopt::qp
