#include "cyclopt/studies/resolved_sensitivity.hpp"

#include "cyclopt/nlp/solve.hpp"
#include "cyclopt/studies/walker_family.hpp"
#include "cyclopt/walker/model_parameters.hpp"

#include <stdexcept>

namespace cyclopt::studies {

ResolvedSensitivity resolved_sensitivity(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                                         const Eigen::VectorXd& z, const nlp::SolverSummary& at, const std::string& parameter,
                                         double relative_step, const nlp::SolverOptions& solver) {
  if (!(relative_step > 0.0 && relative_step < 1.0)) throw std::invalid_argument("relative_step: must be in (0, 1)");
  const ParametricProblem family = walker_family(model, problem, parameter);  // throws for free or derived parameters
  ResolvedSensitivity r;
  r.name = parameter;
  r.value = walker::model_parameters(model)(walker::model_parameter_index(model, parameter));
  if (r.value == 0.0) throw std::invalid_argument("parameter: " + parameter + " is 0, a relative step is undefined");
  nlp::SolverOptions so = solver;
  if (so.solver == nlp::SolverKind::ipopt && !so.ipopt.warm_start)
    so.ipopt.warm_start = nlp::IpoptWarmStart{at.equality_multipliers, at.inequality_multipliers, at.bound_multipliers};
  r.converged = true;
  for (const double direction : {-1.0, 1.0}) {
    const nlp::SolverSummary s = nlp::solve(*family.at(r.value * (1.0 + direction * relative_step)), so, z);
    (direction < 0 ? r.objective_decrease : r.objective_increase) = s.objective;
    r.iterations += s.iterations;
    r.seconds += s.wall_seconds;
    if (s.termination != nlp::Termination::converged) {
      r.converged = false;
      r.message += std::string(direction < 0 ? "decrease: " : "increase: ") + nlp::to_string(s.termination) + "; ";
    }
  }
  r.derivative = (r.objective_increase - r.objective_decrease) / (2.0 * relative_step * r.value);
  return r;
}

}  // namespace cyclopt::studies
