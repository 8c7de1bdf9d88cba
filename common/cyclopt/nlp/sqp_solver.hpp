#pragma once
// The seed's SQP line-search method with per-constraint l1 merit function (seed 001,
// section 6.2.4, Algorithm 1; parameters SolverOptions::sqp, defaults Table 6.2):
//
// - QP subproblem (6.7) solved by the dense active-set solver, warm-started with the previous
//   working set; penalties from its multipliers (6.9);
// - incompatible QP: l1 relaxation (6.13) with a scalar penalty (6.10), raised by rho until the
//   LP (6.14) in the trust region Delta_k certifies enough decrease of the linearised violation
//   (steps 4-7); infeasible stationary point detection (step 5);
// - backtracking on the l1 merit (6.15) with the "no real solution" rule: a failing evaluation
//   shortens the step (step 9) and is never fatal unless even tiny steps fail;
// - EQP-projection second-order correction (6.16)-(6.19) (steps 11-12);
// - damped BFGS (6.20)-(6.22), W_1 = I with (6.25) or from SqpOptions::lagrangian_hessian (6.24);
// - least-squares multipliers (6.26) for the KKT test (step 2) and BFGS.
//
// Deviations, all documented where they occur: simple bounds are hard constraints of every
// subproblem and trial points are projected onto them; the active set of (6.26)/(6.17) is the QP
// working set (plus violated constraints for the SOC); the line search is sequential (the seed
// evaluates the backtracking sequence in parallel, step 12); OCR-garbled steps 14/15 use |d_k|_inf.
// TolOpt/TolCon/MaxIter/MaxTime are SolverOptions::optimality_tolerance/constraint_tolerance/
// max_iterations/max_wall_seconds; an iterate is a KKT point when, additionally, its
// least-squares inequality and bound multipliers have the right sign (within TolOpt).
// print_level 1 prints one line per iteration, 2 also the QP subproblem iteration counts.

#include "cyclopt/nlp/problem.hpp"
#include "cyclopt/nlp/solver_options.hpp"

#include <Eigen/Core>

namespace cyclopt::nlp {

SolverSummary solve_with_sqp(Problem& problem, const SolverOptions& options, const Eigen::VectorXd& x0);

}  // namespace cyclopt::nlp
