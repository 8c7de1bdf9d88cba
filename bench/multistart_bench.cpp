// Issue 4, acceptance 4: wall time of a multistart of N starts at one speed, as the service's
// walker multistart job runs it: starts are perturbations (scale rad N(0,1) per entry, redrawn
// until real) of the automatic starting gait, solved in parallel on all cores. Prints KKT
// successes, distinct optima with their counts, median and total solve time and the wall time.
//
// usage: multistart_bench [foot = point] [speed = 1.3] [N = 20] [configuration = sqp-dh] [scale = 0.05]
#include "bench_foot.hpp"
#include "cyclopt/nlp/multistart.hpp"
#include "cyclopt/walker/gait_problem.hpp"
#include "cyclopt/walker/starting_gait.hpp"
#include "machine_info.hpp"
#include "solver_configuration.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

using namespace cyclopt;

int main(int argc, char** argv) {
  const std::string foot_name = argc > 1 ? argv[1] : "point";
  const double speed = argc > 2 ? std::atof(argv[2]) : 1.3;
  const int n = argc > 3 ? std::atoi(argv[3]) : 20;
  const std::string config = argc > 4 ? argv[4] : "sqp-dh";
  const double scale = argc > 5 ? std::atof(argv[5]) : 0.05;
  std::printf("multistart_bench on %s\n", bench::machine_line().c_str());
  const walker::WalkerModel<double> model = walker::make_walker_model(cyclopt::bench::bench_foot(foot_name));
  const walker::GaitProblemOptions po{walker::Objective::mechanical, speed, walker::Quadrature::trapezoid, {}};
  const walker::GaitEvaluator ev(model);
  const Eigen::VectorXd centre = walker::gait_start(ev, speed, {}).x;
  const walker::GaitProblem shape(model, po);
  nlp::MultistartOptions mo;
  mo.num_starts = n;
  mo.base_seed = 1;
  mo.solver = bench::solver_configuration(config);
  mo.objective_tolerance = 1e-5;
  mo.x_tolerance = 1e-2;
  const nlp::MultistartResult r = nlp::multistart(
      [&] { return std::make_unique<walker::GaitProblem>(model, po); },
      [&](std::mt19937_64& rng) { return shape.initial_point(walker::perturbed_gait(ev, centre, scale, rng)); }, mo);
  std::vector<double> times;
  double total = 0.0;
  int iterations = 0;
  for (const nlp::SolverSummary& s : r.runs) times.push_back(s.wall_seconds), total += s.wall_seconds, iterations += s.iterations;
  std::sort(times.begin(), times.end());
  std::printf("%s f_mech %.2f m/s, %s, %d starts (scale %.3f): %d/%d KKT, %zu optima, %d iterations, median %.2f s, total %.1f s, "
              "WALL %.1f s\n",
              foot_name.c_str(), speed, config.c_str(), n, scale, r.successes, n, r.optima.size(), iterations, times[times.size() / 2],
              total, r.wall_seconds);
  // Per run: where the time of a multistart goes (the tails: runs that end at MaxIter).
  for (std::size_t i = 0; i < r.runs.size(); ++i)
    std::printf("  run %2zu: %-16s %5d iterations %6.2f s  f_mech %.8f\n", i, nlp::to_string(r.runs[i].termination),
                r.runs[i].iterations, r.runs[i].wall_seconds, r.runs[i].objective);
  for (std::size_t k = 0; k < std::min<std::size_t>(r.optima.size(), 5); ++k)
    std::printf("  optimum %zu: f_mech %.8f reached by %zu starts\n", k + 1, r.optima[k].objective, r.optima[k].starts.size());
}
