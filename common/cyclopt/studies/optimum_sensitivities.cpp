#include "cyclopt/studies/optimum_sensitivities.hpp"

#include "cyclopt/nlp/solve.hpp"

#include <cstdio>
#include <stdexcept>

namespace cyclopt::studies {
namespace {

std::string scientific(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1e", x);
  return b;
}

}  // namespace

std::optional<OptimumSensitivities> optimum_sensitivities(const walker::WalkerModel<double>& model,
                                                          const walker::GaitProblemOptions& problem,
                                                          const walker::GaitOptimum& opt,
                                                          const std::vector<std::string>& parameters,
                                                          const std::function<bool()>& should_stop) {
  if (opt.summary.termination != nlp::Termination::converged) return std::nullopt;
  nlp::SolverOptions polish;
  polish.solver = nlp::SolverKind::ipopt;
  polish.optimality_tolerance = polish.constraint_tolerance = 1e-11;
  polish.max_iterations = 200;
  polish.ipopt.difference_hessian_start = true;
  polish.ipopt.warm_start = nlp::IpoptWarmStart{opt.summary.equality_multipliers, opt.summary.inequality_multipliers,
                                                opt.summary.bound_multipliers};
  polish.should_stop = should_stop;
  walker::GaitProblem gait_problem(model, problem);
  const nlp::SolverSummary polished = nlp::solve(gait_problem, polish, opt.z);
  const bool use_polish = polished.termination == nlp::Termination::converged;
  const nlp::SolverSummary& at = use_polish ? polished : opt.summary;
  OptimumSensitivities r;
  r.multipliers = use_polish ? "Ipopt polish of the optimum to 1e-11 (" + std::to_string(polished.iterations) +
                                   " iterations, f changed by " + scientific(polished.objective - opt.summary.objective) + ")"
                             : "the solve's own (the Ipopt polish ended " + std::string(nlp::to_string(polished.termination)) + ")";
  try {
    KktSensitivityOptions o;
    o.parameters = parameters;
    r.kkt = kkt_sensitivity(model, problem, at.x, at, o);
    r.kkt.seconds += polished.wall_seconds;
    r.evaluated = true;
    if (!(r.kkt.lagrangian_gradient <= kMaxLagrangianGradient))
      r.unavailable = "multipliers unusable: |grad_z L|_inf = " + scientific(r.kkt.lagrangian_gradient) + " > " +
                      scientific(kMaxLagrangianGradient);
  } catch (const std::invalid_argument& e) {
    r.unavailable = std::string("no KKT sensitivities: ") + e.what();
  }
  return r;
}

}  // namespace cyclopt::studies
