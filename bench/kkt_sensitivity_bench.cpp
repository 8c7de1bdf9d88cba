// Sensitivities of the optimal f_mech from the KKT point (studies/kkt_sensitivity.hpp) against a
// central difference of warm-started re-solves (studies/resolved_sensitivity.hpp), per parameter,
// with the time of each (issue 15 acceptance 5; bench/results/kkt_sensitivity_bench.txt).
//
// usage: kkt_sensitivity_bench [FOOT] [SPEED] [DENSITY] [RELATIVE_STEP] [all]
//   defaults P2-shoes-left-HMT 2.3 10 1e-4; DENSITY 0 keeps the preset's independent masses;
//   "all": every model parameter (segments too), otherwise the foot's parameters and rho.
#include "bench_foot.hpp"
#include "cyclopt/studies/kkt_sensitivity.hpp"
#include "cyclopt/studies/resolved_sensitivity.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"
#include "cyclopt/walker/model_parameters.hpp"
#include "machine_info.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace cyclopt;

int main(int argc, char** argv) {
  const std::string foot_name = argc > 1 ? argv[1] : "P2-shoes-left-HMT";
  const double speed = argc > 2 ? std::atof(argv[2]) : 2.3, density = argc > 3 ? std::atof(argv[3]) : 10.0;
  const double h = argc > 4 ? std::atof(argv[4]) : 1e-4;
  const bool all = argc > 5 && std::string(argv[5]) == "all";
  foot::FootSpec spec = bench::bench_foot(foot_name);
  if (density > 0) spec.density = density;
  const walker::WalkerModel<double> model = walker::make_walker_model(spec);
  const walker::GaitProblemOptions po{walker::Objective::mechanical, speed, walker::Quadrature::trapezoid, {}};
  std::printf("kkt_sensitivity_bench on %s, %s\n", bench::machine_line().c_str(), bench::load_average().c_str());
  std::printf("foot %s, rho %g, %.2f m/s, f_mech, P = %d; re-solve step h = %g relative\n", foot_name.c_str(), density, speed,
              model.constants.points, h);
  const walker::GaitOptimum start = walker::optimise_gait(model, po, nlp::seed_table_6_2_options());
  nlp::SolverOptions tight;
  tight.solver = nlp::SolverKind::ipopt;
  tight.optimality_tolerance = tight.constraint_tolerance = 1e-11;
  tight.ipopt.difference_hessian_start = true;
  tight.ipopt.warm_start = nlp::IpoptWarmStart{start.summary.equality_multipliers, start.summary.inequality_multipliers,
                                               start.summary.bound_multipliers};
  walker::GaitProblem problem(model, po);
  const nlp::SolverSummary opt = walker::optimise_gait(model, po, tight, walker::GaitProblem(model, po).gait_parameters(start.z)).summary;
  std::printf("optimum: SQP %s f %.10f, polished by Ipopt: %s f %.12f kkt %.1e, %d iterations\n",
              nlp::to_string(start.summary.termination), start.summary.objective, nlp::to_string(opt.termination),
              opt.objective, opt.kkt_error, opt.iterations);
  if (opt.termination != nlp::Termination::converged) return 1;
  studies::KktSensitivityOptions ko;
  if (!all) {
    const std::vector<std::string> names = walker::model_parameter_names(model);
    for (const std::string& n : studies::sensitivity_parameters(model, po))
      if (walker::model_parameter_index(model, n) >= walker::segment_parameter_count && n != "theta_F0") ko.parameters.push_back(n);
  }
  const studies::KktSensitivity k = studies::kkt_sensitivity(model, po, opt.x, opt, ko);
  std::printf("KKT: |grad L| %.1e, %d active rows, unique multipliers %s, weakly active %zu, %.3f s for %zu parameters\n",
              k.lagrangian_gradient, k.active_constraints, k.unique_multipliers ? "yes" : "no", k.weakly_active.size(), k.seconds,
              k.parameters.size());
  for (const std::string& w : k.weakly_active) std::printf("  weakly active: %s\n", w.c_str());
  std::printf("%-9s %12s %14s %14s %10s %9s %9s %5s %8s %s\n", "param", "value", "KKT df/dp", "re-solve", "rel err", "range-",
              "range+", "kink", "resolve s", "limiting rows");
  double resolve_seconds = 0.0, worst = 0.0;
  for (const studies::ParameterSensitivity& p : k.parameters) {
    const studies::ResolvedSensitivity r = studies::resolved_sensitivity(model, po, opt.x, opt, p.name, h, tight);
    resolve_seconds += r.seconds;
    const double err = std::abs(p.derivative - r.derivative) / std::max(std::abs(r.derivative), 1e-300);
    if (!p.kink && r.converged) worst = std::max(worst, err);
    std::printf("%-9s %12.6g %14.7e %14.7e %10.2e %9.2e %9.2e %5s %8.2f %s | %s%s\n", p.name.c_str(), p.value, p.derivative,
                r.derivative, err, p.decrease.relative_change, p.increase.relative_change, p.kink ? "yes" : "no", r.seconds,
                p.decrease.constraint.c_str(), p.increase.constraint.c_str(), r.converged ? "" : ("  NOT CONVERGED " + r.message).c_str());
  }
  std::printf("max rel err without kink %.2e; KKT sensitivities %.3f s, re-solves %.2f s (%.2f s per parameter)\n", worst,
              k.seconds, resolve_seconds, resolve_seconds / static_cast<double>(k.parameters.size()));
}
