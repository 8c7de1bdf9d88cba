#include "cyclopt/qp/convex_solve.hpp"

#include "cyclopt/qp/dual_active_set_solver.hpp"

namespace cyclopt::qp {

QpSolution solve_convex(const QuadraticProgram& qp, const ActiveSetOptions& options, const WorkingSet& warm_start,
                        const ScreeningOptions& screening) {
  if (is_strictly_convex(qp.hessian, options.curvature_tolerance)) return solve_dual_active_set(qp, options);
  return solve_screened(qp, options, warm_start, screening);
}

}  // namespace cyclopt::qp
