#include "cyclopt/jobs/solver_fields.hpp"

namespace cyclopt::jobs {

nlp::SolverOptions solver_options(const service::SolverOverrides& overrides, const nlp::SolverOptions& base) {
  nlp::SolverOptions o = base;
  if (overrides.solver) o.solver = nlp::parse_solver_kind(*overrides.solver, "solver.solver");
  o.max_iterations = overrides.max_iterations.value_or(o.max_iterations);
  o.optimality_tolerance = overrides.optimality_tolerance.value_or(o.optimality_tolerance);
  o.constraint_tolerance = overrides.constraint_tolerance.value_or(o.constraint_tolerance);
  o.print_level = overrides.print_level.value_or(o.print_level);
  return o;
}

nlohmann::json solver_json(const nlp::SolverOptions& options) {
  return {{"solver", nlp::to_string(options.solver)},
          {"max_iterations", options.max_iterations},
          {"optimality_tolerance", options.optimality_tolerance},
          {"constraint_tolerance", options.constraint_tolerance},
          {"print_level", options.print_level}};
}

}  // namespace cyclopt::jobs
