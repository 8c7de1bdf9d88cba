#include "cyclopt/nlp/solver_options.hpp"

#include <cmath>
#include <stdexcept>

namespace cyclopt::nlp {

const char* to_string(Termination t) {
  switch (t) {
    case Termination::converged: return "converged";
    case Termination::acceptable: return "acceptable";
    case Termination::max_iterations: return "max_iterations";
    case Termination::time_limit: return "time_limit";
    case Termination::infeasible: return "infeasible";
    case Termination::evaluation_failure: return "evaluation_failure";
    case Termination::user_stop: return "user_stop";
    case Termination::numerical_failure: return "numerical_failure";
    case Termination::stalled: return "stalled";
  }
  return "unknown";
}

const char* to_string(Optimality o) {
  switch (o) {
    case Optimality::none: return "none";
    case Optimality::kkt: return "KKT";
    case Optimality::nonsmooth_kkt: return "nonsmooth KKT";
  }
  return "unknown";
}

const char* to_string(SolverKind kind) {
  switch (kind) {
    case SolverKind::ipopt: return "ipopt";
    case SolverKind::sqp: return "sqp";
  }
  return "unknown";
}

SolverKind parse_solver_kind(const std::string& text, const std::string& field) {
  if (text == "ipopt") return SolverKind::ipopt;
  if (text == "sqp") return SolverKind::sqp;
  throw std::invalid_argument(field + ": unknown solver '" + text + "'; allowed: ipopt, sqp");
}

namespace {

void require(bool ok, const char* field, const char* range) {
  if (!ok) throw std::invalid_argument(std::string("SolverOptions.") + field + ": must be " + range);
}

}  // namespace

void validate(const SolverOptions& o) {
  require(o.solver == SolverKind::ipopt || o.solver == SolverKind::sqp, "solver", "ipopt or sqp");
  require(o.max_iterations >= 1, "max_iterations", ">= 1");
  require(o.optimality_tolerance > 0, "optimality_tolerance", "> 0");
  require(o.constraint_tolerance > 0, "constraint_tolerance", "> 0");
  require(o.max_wall_seconds > 0, "max_wall_seconds", "> 0 (infinity for no limit)");
  require(o.print_level >= 0 && o.print_level <= 12, "print_level", "in [0, 12]");
  require(o.ipopt.limited_memory_max_history >= 1, "ipopt.limited_memory_max_history", ">= 1");
  require(o.ipopt.mu_strategy == "monotone" || o.ipopt.mu_strategy == "adaptive", "ipopt.mu_strategy",
          "\"monotone\" or \"adaptive\"");
  require(!o.ipopt.warm_start || o.ipopt.warm_start->mu_init > 0, "ipopt.warm_start.mu_init", "> 0");
  require(o.ipopt.difference_hessian_every >= 0, "ipopt.difference_hessian_every", ">= 0 (0: never)");
  const SqpOptions& s = o.sqp;
  require(s.initial_penalty > 0, "sqp.initial_penalty", "> 0");
  require(s.penalty_increase > 1, "sqp.penalty_increase", "> 1");
  require(s.epsilon1 > 0 && s.epsilon1 <= 1, "sqp.epsilon1", "in (0, 1]");
  // Algorithm 1 asks for epsilon2 in (0, epsilon1), but Table 6.2 sets both to 0.1: (0, epsilon1] admits the table.
  require(s.epsilon2 > 0 && s.epsilon2 <= s.epsilon1, "sqp.epsilon2", "in (0, sqp.epsilon1]");
  require(s.armijo > 0 && s.armijo < 1, "sqp.armijo", "in (0, 1)");
  require(s.backtracking > 0 && s.backtracking < 1, "sqp.backtracking", "in (0, 1)");
  require(s.relative_min_penalty > 0 && s.relative_min_penalty < 1, "sqp.relative_min_penalty", "in (0, 1)");
  require(s.min_trust_radius > 0, "sqp.min_trust_radius", "> 0");
  require(s.max_trust_radius >= s.min_trust_radius, "sqp.max_trust_radius", ">= sqp.min_trust_radius");
  require(s.initial_trust_radius >= s.min_trust_radius && s.initial_trust_radius <= s.max_trust_radius,
          "sqp.initial_trust_radius", "in [sqp.min_trust_radius, sqp.max_trust_radius]");
  require(s.step_tolerance > 0, "sqp.step_tolerance", "> 0");
  require(s.max_function_evaluations >= 1, "sqp.max_function_evaluations", ">= 1");
  require(!std::isnan(s.objective_limit), "sqp.objective_limit", "a number (-infinity for no limit)");
  require(s.max_backtracking_steps >= 1, "sqp.max_backtracking_steps", ">= 1");
  require(s.difference_hessian_every >= 0, "sqp.difference_hessian_every", ">= 0 (0: never)");
  require(s.progress_window >= 0, "sqp.progress_window", ">= 0 (0: never)");
  require(s.max_qp_iterations >= 0, "sqp.max_qp_iterations", ">= 0 (0: never)");
  require(s.progress_min_decrease > 0 && s.progress_min_decrease < 1, "sqp.progress_min_decrease", "in (0, 1)");
  require(s.kinks.model_band > 0 && s.kinks.model_band < 1, "sqp.kinks.model_band", "in (0, 1)");
  require(s.kinks.test_band > 0 && s.kinks.test_band <= s.kinks.model_band, "sqp.kinks.test_band", "in (0, sqp.kinks.model_band]");
  require(s.kinks.active_tolerance >= 0, "sqp.kinks.active_tolerance", ">= 0");
}

SolverOptions seed_table_6_2_options() {
  SolverOptions o;
  o.solver = SolverKind::sqp;
  o.optimality_tolerance = 1e-5;
  o.constraint_tolerance = 1e-10;
  o.max_iterations = 2000;
  return o;
}

}  // namespace cyclopt::nlp
