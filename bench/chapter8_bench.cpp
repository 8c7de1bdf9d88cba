// The chapter-8.1 experiment of seed 001 (Fig. 8.1) as a benchmark: foot HM of subject P1, left,
// barefoot (Table 4.2), objective f_mech (5.102), v_bar = 1.3 m/s. The seed perturbs a solution
// "found by trying"; here x* is the better of two SQP solves from the automatic starting gait
// (W_1 = I and W_1 from the difference Hessian). N random perturbations of x* with a real periodic
// solution are the starts, the same for every solver configuration (multistart in parallel on all
// cores). Printed per configuration: KKT successes, distinct optima, starts reaching the best
// optimum, median and total solve time, wall time, and one line per start. The seed reports
// 100/100 KKT and 45/100 at the best optimum for its SQP (W_1 = I, MaxIter = 3000).
//
// usage: chapter8_bench [N = 100] [configurations = sqp,sqp-dh,ipopt] [scale = 0.05] [replay]
//   sqp: W_1 = I, then (6.25), as the seed's comparison; sqp-dh: W_1 from (6.24) on the difference
//   Hessian (SqpOptions::difference_hessian); ipopt: Ipopt with the adapter's defaults.
//   replay = k: solve only start k (seed 1000 + k) with the first configuration, printing its log.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/nlp/multistart.hpp"
#include "cyclopt/nlp/solve.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"
#include "machine_info.hpp"
#include "solver_configuration.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>

using namespace cyclopt;
using namespace cyclopt::walker;

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 100;
  const std::string solvers = argc > 2 ? argv[2] : "sqp,sqp-dh,ipopt";
  const double scale = argc > 3 ? std::atof(argv[3]) : 0.05;
  std::printf("chapter8_bench on %s\n", cyclopt::bench::machine_line().c_str());
  const WalkerModel<double> model = make_walker_model(foot::foot_preset("P1-barefoot-left-HM").spec);
  const GaitProblemOptions po{Objective::mechanical, 1.3, Quadrature::trapezoid, {}};
  GaitOptimum ref;
  for (const char* name : {"sqp", "sqp-dh"}) {
    GaitOptimum r = optimise_gait(model, po, cyclopt::bench::solver_configuration(name));
    std::printf("reference candidate (%s from the starting gait): f_mech %.8f (%s, %d iterations, %.1f s)\n", name,
                r.summary.objective, nlp::to_string(r.summary.termination), r.summary.iterations, r.summary.wall_seconds);
    if (r.summary.success() && (!ref.summary.success() || r.summary.objective < ref.summary.objective)) ref = std::move(r);
  }
  if (!ref.summary.success()) {
    std::printf("no reference optimum: both SQP solves from the starting gait failed\n");
    return 1;
  }
  const GaitEvaluator ev(model);
  const GaitProblem shape(model, po);
  if (argc > 4) {
    const int k = std::atoi(argv[4]);
    std::mt19937_64 rng(1000 + static_cast<std::uint64_t>(k));
    nlp::SolverOptions replay = cyclopt::bench::solver_configuration(solvers.substr(0, solvers.find(',')));
    replay.print_level = 2;
    GaitProblem problem(model, po);
    const nlp::SolverSummary s = nlp::solve(problem, replay, shape.initial_point(perturbed_gait(ev, ref.z, scale, rng)));
    std::printf("replay of start %d: %s, %d it, f_mech %.8f, kkt %.1e: %s\n", k, nlp::to_string(s.termination), s.iterations,
                s.objective, s.kkt_error, s.message.c_str());
    return 0;
  }
  std::printf("x* f_mech %.8f; %d starts: x* + %.3f rad N(0,1) per entry, redrawn until real (seeds 1000..%d)\n\n",
              ref.summary.objective, n, scale, 999 + n);
  std::printf("%-6s %8s %8s %10s %12s %12s %10s %s\n", "solver", "KKT", "optima", "at best", "median (s)", "total (s)",
              "wall (s)", "best f_mech");
  std::stringstream list(solvers);
  std::string name;
  while (std::getline(list, name, ',')) {
    nlp::MultistartOptions mo;
    mo.num_starts = n;
    mo.base_seed = 1000;
    mo.solver = cyclopt::bench::solver_configuration(name);
    mo.objective_tolerance = 1e-5;
    mo.x_tolerance = 1e-2;
    const nlp::MultistartResult r = nlp::multistart(
        [&] { return std::make_unique<GaitProblem>(model, po); },
        [&](std::mt19937_64& rng) { return shape.initial_point(perturbed_gait(ev, ref.z, scale, rng)); }, mo);
    std::vector<double> times;
    double total = 0.0;
    for (const nlp::SolverSummary& s : r.runs) {
      times.push_back(s.wall_seconds);
      total += s.wall_seconds;
    }
    std::sort(times.begin(), times.end());
    const double best = std::min(r.optima.empty() ? 1e300 : r.optima.front().objective, ref.summary.objective);
    int at_best = 0;
    for (const nlp::SolverSummary& s : r.runs)
      if (s.success() && std::abs(s.objective - best) <= 1e-5 * std::max(1.0, std::abs(best))) ++at_best;
    std::printf("%-6s %5d/%-3d %8zu %7d/%-3d %12.2f %12.1f %10.1f %.8f\n", name.c_str(), r.successes, n, r.optima.size(),
                at_best, n, times[times.size() / 2], total, r.wall_seconds, best);
    for (std::size_t i = 0; i < r.runs.size(); ++i) {
      const nlp::SolverSummary& s = r.runs[i];
      std::printf("         start %2zu: %-18s %5d it %6d f + %5d J  f_mech %.8f  kkt %.1e  %6.2f s\n", i, nlp::to_string(s.termination),
                  s.iterations, s.function_evaluations, s.jacobian_evaluations, s.objective, s.kkt_error, s.wall_seconds);
    }
    for (std::size_t k = 0; k < std::min<std::size_t>(r.optima.size(), 5); ++k)
      std::printf("         optimum %zu: f_mech %.8f reached by %zu starts\n", k + 1, r.optima[k].objective,
                  r.optima[k].starts.size());
  }
}
