#pragma once
// Constraint screening for QPs with many inequality rows of which few can become active (the
// SQP subproblems of the walker: 2003 rows, most with c_u far below 0). The active-set solver
// (active_set_solver.hpp) runs on a working set of rows - those whose right-hand side is within
// `margin` of 0 plus the warm start's - and every row violated at the solution is added and the
// reduced QP re-solved, warm-started, until no omitted row is violated. The result is the full
// QP's: its feasible set lies inside the reduced one's, so a reduced optimum satisfying every row
// is a full optimum (omitted rows have multiplier 0), and a reduced infeasibility proves the full
// one. An unbounded reduced QP is re-solved with all rows (an omitted row may bound the ray).

#include "cyclopt/qp/active_set_solver.hpp"
#include "cyclopt/qp/quadratic_program.hpp"

namespace cyclopt::qp {

struct ScreeningOptions {
  // Rows with b_in_i <= margin * max(1, |A_in row i|) start in the reduced QP; admissible: any
  // number (+infinity: every row, i.e. no screening).
  double margin = 0.5;
};

// Same contract as solve_active_set (multipliers and working set in the full QP's indices);
// `iterations` counts the active-set iterations of all reduced solves.
QpSolution solve_screened(const QuadraticProgram& qp, const ActiveSetOptions& options, const WorkingSet& warm_start,
                          const ScreeningOptions& screening);

}  // namespace cyclopt::qp
