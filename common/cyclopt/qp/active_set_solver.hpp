#pragma once
// Dense primal active-set method for the convex quadratic programs of quadratic_program.hpp
// (Nocedal & Wright, "Numerical Optimization", Algorithm 16.3, null-space variant), the QP
// subproblem solver of the seed's SQP (seed 001 section 6.2.4 uses Matlab's active-set `qpsub`
// for the same purpose: semidefinite Hessians of eq. (6.13)/(6.14) and a warm-started working set).
//
// Phase 1 minimises the largest constraint violation t (an LP in (x, t)) with the same
// iteration, keeping satisfied simple bounds hard; phase 2 then keeps primal feasibility. Active
// simple bounds fix their variables, so the null space is computed on the free variables only,
// and the reduced Hessian is factorised through the variables with curvature only: slacks of
// zero curvature held at 0 (most of those of (6.13)/(6.14)) cost almost nothing. Positive SEMI-definite H is handled: where the
// reduced Hessian has zero curvature and the reduced gradient does not vanish, the step is a
// descent ray that either hits a constraint or proves the QP unbounded. The working set stays
// linearly independent (a blocking constraint is never in the span of the working set; redundant
// equalities and warm-start rows are filtered), so degenerate vertices with more active
// constraints than variables are handled.

#include "cyclopt/qp/quadratic_program.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace cyclopt::qp {

struct ActiveSetOptions {
  int max_iterations = 10000;           // phase 1 + phase 2 iterations; admissible: >= 1
  double feasibility_tolerance = 1e-9;  // absolute, on every constraint residual; admissible: > 0
  // A working-set multiplier below -optimality_tolerance * max(1, max|multiplier|) has the wrong
  // sign; a zero-curvature reduced gradient below optimality_tolerance * max(1, |Hx + g|_inf)
  // counts as zero. Admissible: > 0.
  double optimality_tolerance = 1e-9;
  // Reduced-Hessian eigenvalues below curvature_tolerance * max(1, max|H_ij|) count as zero
  // curvature. Admissible: > 0.
  double curvature_tolerance = 1e-10;
};

enum class QpStatus {
  optimal,         // KKT point (global minimiser: the QP is convex)
  infeasible,      // no x satisfies the constraints within feasibility_tolerance
  unbounded,       // a feasible ray of zero curvature along which the objective decreases
  max_iterations,
};

const char* to_string(QpStatus status);

// Constraints held at equality. The solution's working set warm-starts the next, similar QP.
struct WorkingSet {
  std::vector<int> inequalities;  // rows of A_in
  std::vector<int> lower_bounds;  // variables held at their lower bound
  std::vector<int> upper_bounds;  // variables held at their upper bound
  bool empty() const { return inequalities.empty() && lower_bounds.empty() && upper_bounds.empty(); }
};

// Multiplier signs: at an optimum
//   H x + g + A_eq' y_eq + A_in' y_in - z_lower + z_upper = 0,   y_in, z_lower, z_upper >= 0,
// i.e. the Lagrangian is 1/2 x'Hx + g'x + y_eq'(A_eq x - b_eq) + y_in'(A_in x - b_in)
// + z_lower'(lower - x) + z_upper'(x - upper). Multipliers of redundant (dependent) equality rows are 0.
struct QpSolution {
  QpStatus status = QpStatus::infeasible;
  std::string message;
  int iterations = 0;            // phase 1 + phase 2
  int phase_one_iterations = 0;
  Eigen::VectorXd x;             // optimum; for infeasible: the phase-1 point of least violation
  double objective = 0.0;
  Eigen::VectorXd equality_multipliers;     // y_eq, size m_eq
  Eigen::VectorXd inequality_multipliers;   // y_in, size m_in
  Eigen::VectorXd lower_bound_multipliers;  // z_lower, size n
  Eigen::VectorXd upper_bound_multipliers;  // z_upper, size n
  WorkingSet working_set;                   // active constraints at x
};

// warm_start: a guess of the active set (e.g. the previous SQP iteration's); rows that are
// linearly dependent or inconsistent with the rest are dropped, so any guess is safe.
QpSolution solve_active_set(const QuadraticProgram& qp, const ActiveSetOptions& options = {},
                            const WorkingSet& warm_start = {});

}  // namespace cyclopt::qp
