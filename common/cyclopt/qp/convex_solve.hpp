#pragma once
// The QP solver the SQP and the continuation predictor call: the dual method
// (dual_active_set_solver.hpp) when H is positive definite - the QP (6.7) with the damped-BFGS
// W_k - and otherwise the primal active-set method on screened rows (screened_solve.hpp),
// warm-started: the semidefinite l1 subproblems (6.13)/(6.14), whose slacks have no curvature.

#include "cyclopt/qp/active_set_solver.hpp"
#include "cyclopt/qp/quadratic_program.hpp"
#include "cyclopt/qp/screened_solve.hpp"

namespace cyclopt::qp {

QpSolution solve_convex(const QuadraticProgram& qp, const ActiveSetOptions& options, const WorkingSet& warm_start,
                        const ScreeningOptions& screening);

}  // namespace cyclopt::qp
