// The Fig. 8.4 experiment of seed 001 (section 8.2) as a benchmark: an optimal gait at 1.3 m/s is
// continued to 2.3 m/s by (a) the QPSQP method (Algorithm 2, requested values every 0.1 m/s, SQP
// corrector), (b) Ipopt warm starts at every 0.1 m/s (trivial predictor), (c) the trivial
// predictor with the fixed step 0.2 m/s and the SQP corrector. Printed per method: corrector
// iterations, QP-predictor steps, wall time, curve jumps, and per point the speed, curve id and
// f_mech (progress per point on stderr). The seed starts from its second-best optimum x_2*; here
// the start is the SQP optimum from the automatic starting gait.
//
// usage: continuation_bench [foot = P1-barefoot-left-HM] [from = 1.3] [to = 2.3] [methods = qpsqp,ipopt,fixed]
#include "cyclopt/continuation/continuation_solver.hpp"
#include "cyclopt/studies/walker_family.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"
#include "machine_info.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

using namespace cyclopt;
using namespace cyclopt::continuation;
using namespace cyclopt::studies;

namespace {

struct Method {
  const char* key;
  const char* name;
  Predictor predictor;
  nlp::SolverKind corrector;
  double fixed_step;
};

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  const std::string foot_name = argc > 1 ? argv[1] : "P1-barefoot-left-HM";
  const double from = argc > 2 ? std::atof(argv[2]) : 1.3, to = argc > 3 ? std::atof(argv[3]) : 2.3;
  const std::string selected = argc > 4 ? argv[4] : "qpsqp,ipopt,fixed";
  std::printf("continuation_bench on %s\n", cyclopt::bench::machine_line().c_str());
  const walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset(foot_name).spec);
  const walker::GaitProblemOptions po{walker::Objective::mechanical, from, walker::Quadrature::trapezoid, {}};
  nlp::SolverOptions sqp = nlp::seed_table_6_2_options();
  sqp.sqp.difference_hessian = true;  // W_1 of (6.24), the seed's choice (W_1 = I only for its fmincon comparison)
  const walker::GaitOptimum start = walker::optimise_gait(model, po, sqp);
  std::printf("foot %s, f_mech, start: SQP from the automatic starting gait at %.2f m/s: %s, f %.8f, %d iterations, %.1f s\n\n",
              foot_name.c_str(), from, nlp::to_string(start.summary.termination), start.summary.objective,
              start.summary.iterations, start.summary.wall_seconds);
  if (!start.summary.success()) return 1;
  std::vector<double> grid;
  for (int i = 0; from + 0.1 * i <= to + 1e-9; ++i) grid.push_back(from + 0.1 * i);
  const ParametricProblem family = walker_family(model, po, "speed");
  const Method methods[] = {{"qpsqp", "QPSQP (SQP corrector)", Predictor::qp, nlp::SolverKind::sqp, 0.0},
                            {"ipopt", "Ipopt warm start, dv = 0.1", Predictor::trivial, nlp::SolverKind::ipopt, 0.0},
                            {"fixed", "fixed step dv = 0.2 (SQP)", Predictor::trivial, nlp::SolverKind::sqp, 0.2}};
  std::printf("%-28s %8s %10s %10s %9s %7s %10s %s\n", "method", "points", "corrector", "predictor", "time (s)", "jumps",
              "f at end", "finished");
  std::vector<ContinuationResult> results;
  std::vector<const Method*> ran;
  for (const Method& m : methods) {
    if (selected.find(m.key) == std::string::npos) continue;
    ran.push_back(&m);
    ContinuationOptions o;
    o.predictor = m.predictor;
    o.fixed_step = m.fixed_step;
    o.corrector = sqp;
    o.corrector.solver = m.corrector;
    // Ipopt may not converge on a rolling-foot point; a failing corrector would otherwise take
    // MaxIter = 2000 iterations (~3 min) before the run reports it.
    if (m.corrector == nlp::SolverKind::ipopt) o.corrector.max_wall_seconds = 60.0;
    results.push_back(continue_solution(family, start.z, grid, o, {}, [&m](const CurvePoint& p) {
      std::fprintf(stderr, "  [%s] v %.4f curve %d %s f %.6f, %d corrector iterations, %.1f s\n", m.key, p.parameter, p.curve_id,
                   p.converged ? "ok" : "failed", p.objective, p.corrector.iterations, p.seconds);
      return true;
    }));
    const ContinuationResult& r = results.back();
    std::printf("%-28s %8zu %10d %10d %9.1f %7zu %10.6f %s (%s)\n", m.name, r.points.size(), r.corrector_iterations,
                r.predictor_steps, r.seconds, r.jumps.size(), r.points.back().objective, r.finished ? "yes" : "no",
                r.message.c_str());
    std::fflush(stdout);
  }
  for (std::size_t k = 0; k < results.size(); ++k) {
    std::printf("\n%s: v (m/s), curve, f_mech, corrector iterations, QP-predictor tries/steps, kappa, time (s)\n", ran[k]->name);
    for (const CurvePoint& p : results[k].points)
      std::printf("  %.4f %s curve %d  f %.6f  %4d  %d/%d  %.3f  %.2f%s\n", p.parameter, p.on_grid ? "*" : " ", p.curve_id,
                  p.objective, p.corrector.iterations, p.predictor_attempts, p.predictor_steps, p.kappa, p.seconds,
                  p.converged ? "" : "  (corrector failed)");
    for (const CurveJump& j : results[k].jumps)
      std::printf("  jump curve %d -> %d between v = %.4f and %.4f: f %.6f -> %.6f, relative distance %.3f\n", j.from_curve,
                  j.to_curve, j.from_parameter, j.to_parameter, j.objective_before, j.objective_after, j.relative_distance);
  }
  return 0;
}
