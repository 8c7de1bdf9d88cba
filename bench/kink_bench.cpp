// Issue 52 acceptance 1: the seed multistart of a foot at one speed (the speed sweep's starts:
// perturbations of the automatic starting gait, seed 1 + i, scale 0.05 rad, as
// studies/speed_sweep.cpp's gait_multistart_at) solved at P grid points with each solver
// configuration, one run after the other in this thread. Per run: termination, the optimality test
// passed, iterations, f_mech, and the independently computed stationarity residual
// (independent_stationarity.hpp; kink band eps = 1e-4 W as block "12-06 03:05" item 4, inequalities
// with |c| <= 1e-7 active); per configuration: the runs at a (nonsmooth) KKT point by that residual
// (feasible to 1e-8, residual <= 1e-6) and the CPU seconds of all its runs.
//
// usage: kink_bench [foot = P2-shoes-left-HMT] [speed = 0.3] [starts = 20] [P = 200] [config ...]
//   config: today (the sweep's multistart solver: distant_start_solver of Table 6.2, progress window
//   200, MaxQpIter 20000), kinks (the same with SqpOptions::kinks), kinksN (kinks with TolOpt 10^-N),
//   a suffix -q for the QP budget of distant_start_solver, bandW (today's solver on f_mech rounded on
//   the band W, GaitProblemOptions::positive_power_band; the residual is the exact f_mech's), smooth
//   (the smoothing homotopy of walker/smoothing_homotopy.hpp with today's solver, polished by it),
//   smooth+CONFIG (polished by CONFIG's solver), smooth-raw (no polish), CONFIG-nobound (CONFIG
//   without SqpOptions::evaluable_step_bound), CONFIG+held[N] (CONFIG's run, then its end point polished on
//   the manifold of its held joints, walker/held_joint_solve.hpp, with TolOpt 10^-N, default Table 6.2's);
//   default: today kinks. KINK_BENCH_ONLY=i runs start i alone.
#include "bench_foot.hpp"
#include "independent_stationarity.hpp"
#include "machine_info.hpp"

#include "cyclopt/nlp/solve.hpp"
#include "cyclopt/walker/distant_start_solver.hpp"
#include "cyclopt/walker/held_joint_solve.hpp"
#include "cyclopt/walker/smoothing_homotopy.hpp"
#include "cyclopt/walker/starting_gait.hpp"

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <random>
#include <string>
#include <vector>

using namespace cyclopt;

namespace {

// studies/speed_sweep.cpp: kQpIterations of the sweep's local solves, and its default seed and scale.
constexpr int kSweepQpIterations = 20000;
constexpr std::uint64_t kSweepSeed = 1;
constexpr double kSweepScale = 0.05;
constexpr double kKinkEps = 1e-4;       // W
constexpr double kActive = 1e-7;        // scaled constraint units
constexpr double kFeasible = 1e-8;
constexpr double kStationary = 1e-6;

struct Configuration {
  nlp::SolverOptions solver;
  double band = 0.0;  // GaitProblemOptions::positive_power_band of the solve (W)
  // The smoothing homotopy (walker/smoothing_homotopy.hpp) with `solver` in every stage, then the
  // exact f_mech's polish with polish_solver (none: the last stage's point is the run's).
  bool homotopy = false;
  std::optional<nlp::SolverOptions> polish_solver;
  // The end point polished on the manifold of its held joints (walker/held_joint_solve.hpp) with
  // `solver` at this TolOpt.
  std::optional<double> held_tolerance;
};

Configuration configuration(const std::string& name) {
  if (const std::size_t plus = name.find("+held"); plus != std::string::npos) {  // CONFIG+held[N]
    Configuration c = configuration(name.substr(0, plus));
    const std::string digits = name.substr(plus + 5);
    c.held_tolerance = digits.empty() ? c.solver.optimality_tolerance : std::pow(10.0, -std::atof(digits.c_str()));
    return c;
  }
  if (name.rfind("smooth", 0) == 0) {  // smooth, smooth+CONFIG, smooth-raw
    Configuration c = configuration("today");
    c.homotopy = true;
    if (name == "smooth") c.polish_solver = c.solver;
    else if (name.rfind("smooth+", 0) == 0) c.polish_solver = configuration(name.substr(7)).solver;
    else if (name != "smooth-raw") {
      std::fprintf(stderr, "configuration '%s': expected smooth, smooth+CONFIG or smooth-raw\n", name.c_str());
      std::exit(1);
    }
    return c;
  }
  if (name.size() > 8 && name.substr(name.size() - 8) == "-nobound") {  // CONFIG-nobound: without the evaluable step bound
    Configuration c = configuration(name.substr(0, name.size() - 8));
    c.solver.sqp.evaluable_step_bound = false;
    return c;
  }
  Configuration c{walker::distant_start_solver(nlp::seed_table_6_2_options()), 0.0, false, std::nullopt, std::nullopt};
  nlp::SolverOptions& o = c.solver;
  o.sqp.progress_window = walker::kMultistartProgressWindow;
  o.sqp.max_qp_iterations = kSweepQpIterations;
  if (name == "today") return c;
  if (name.rfind("band", 0) == 0) {
    c.band = std::atof(name.c_str() + 4);
    return c;
  }
  if (name.rfind("kinks", 0) == 0) {  // kinks[N][-q]
    o.sqp.kinks.enabled = true;
    std::string rest = name.substr(5);
    // -q: the QP budget of distant_start_solver (kDistantStartQpIterations) instead of the sweep's:
    // the dual QP of the kinked subproblem counts its iterations differently.
    if (rest.size() >= 2 && rest.substr(rest.size() - 2) == "-q") {
      o.sqp.max_qp_iterations = walker::kDistantStartQpIterations;
      rest.resize(rest.size() - 2);
    }
    if (!rest.empty()) o.optimality_tolerance = std::pow(10.0, -std::atof(rest.c_str()));  // TolOpt 10^-N
    return c;
  }
  std::fprintf(stderr, "configuration '%s': expected today, bandW, kinks, kinks-q, kinksN or smooth...\n", name.c_str());
  std::exit(1);
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  const std::string foot_name = argc > 1 ? argv[1] : "P2-shoes-left-HMT";
  const double speed = argc > 2 ? std::atof(argv[2]) : 0.3;
  const int starts = argc > 3 ? std::atoi(argv[3]) : 20;
  walker::WalkingConstants constants;
  if (argc > 4) constants.points = std::atoi(argv[4]);
  std::vector<std::string> configs;
  for (int k = 5; k < argc; ++k) configs.emplace_back(argv[k]);
  if (configs.empty()) configs = {"today", "kinks"};
  std::printf("kink_bench on %s, %s at the start\n", bench::machine_line().c_str(), bench::load_average().c_str());
  std::printf("foot %s, %.2f m/s, P = %d, %d starts (seed %llu + i, scale %.2f rad); residual: kink band %.0e W, "
              "active |c| <= %.0e; counted: violation <= %.0e and residual <= %.0e\n",
              foot_name.c_str(), speed, constants.points, starts, static_cast<unsigned long long>(kSweepSeed), kSweepScale,
              kKinkEps, kActive, kFeasible, kStationary);
  const walker::WalkerModel<double> model = walker::make_walker_model(bench::bench_foot(foot_name), constants);
  walker::GaitProblemOptions po;
  po.speed = speed;
  const walker::GaitEvaluator ev(model);
  walker::StartingGaitOptions so;
  so.speed = speed;
  const walker::StartingGait sg = walker::starting_gait(ev, so);
  if (!sg.real) {
    std::printf("no starting gait at %.2f m/s\n", speed);
    return 1;
  }
  const walker::GaitProblem shape(model, po);
  std::vector<Eigen::VectorXd> x0;
  for (int i = 0; i < starts; ++i) {
    std::mt19937_64 rng(kSweepSeed + static_cast<std::uint64_t>(i));
    x0.push_back(shape.initial_point(walker::perturbed_gait(ev, sg.x, kSweepScale, rng)));
  }
  for (const std::string& name : configs) {
    const Configuration c = configuration(name);
    nlp::SolverOptions o = c.solver;
    walker::GaitProblemOptions solve_po = po;
    solve_po.positive_power_band = c.band;
    if (std::getenv("KINK_BENCH_VERBOSE")) o.print_level = std::atoi(std::getenv("KINK_BENCH_VERBOSE"));
    if (std::getenv("KINK_MODEL_BAND")) o.sqp.kinks.model_band = std::atof(std::getenv("KINK_MODEL_BAND"));
    std::printf("\n%s (TolOpt %.0e%s, band %g W):\n", name.c_str(), o.optimality_tolerance, o.sqp.kinks.enabled ? ", kinks modelled" : "",
                c.band);
    std::printf("  run  termination     test           it     f_mech        viol     solver kkt  sample box  interval box  "
                "at kink  CPU s\n");
    int stationary = 0, converged = 0, within_1e4 = 0, within_1e3 = 0;
    double cpu_total = 0.0, best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < starts; ++i) {
      if (std::getenv("KINK_BENCH_ONLY") && std::atoi(std::getenv("KINK_BENCH_ONLY")) != i) continue;
      walker::GaitProblem solved(model, solve_po), problem(model, po);
      const double cpu0 = bench::cpu_seconds();
      nlp::SolverSummary s;
      if (c.homotopy) {
        // The stages here, the polish below: its solver may differ from theirs (smooth+CONFIG).
        walker::SmoothingHomotopyOptions h;
        h.polish = false;
        const walker::SmoothingHomotopySummary hs = walker::solve_by_smoothing(model, po, o, x0[static_cast<size_t>(i)], h);
        s = hs.final();
        if (c.polish_solver) {
          nlp::SolverOptions polish = *c.polish_solver;
          polish.print_level = o.print_level;
          s = nlp::solve(problem, polish, s.x);
        }
        std::printf("       stages (iterations, ! not converged):");
        for (const nlp::SolverSummary& stage : hs.stages) std::printf(" %d%s", stage.iterations, stage.success() ? "" : "!");
        std::printf("\n");
        if (!c.polish_solver) {  // the run's objective is the exact f_mech at the last stage's point
          nlp::Evaluation e;
          if (problem.evaluate(s.x, false, e).ok) s.objective = e.objective;
        }
      } else {
        s = nlp::solve(solved, o, x0[static_cast<size_t>(i)]);
      }
      if (c.held_tolerance) {
        nlp::SolverOptions manifold = o;
        manifold.optimality_tolerance = *c.held_tolerance;
        const walker::HeldJointSolve h = walker::solve_on_held_joints(model, po, manifold, s);
        if (h.manifold) {
          std::printf("       held joints:");
          for (int j : h.joints) std::printf(" %s", walker::joint_name(j));
          std::printf("; on their manifold: %s, %d iterations, f_mech %.8f\n", nlp::to_string(h.manifold->termination),
                      h.manifold->iterations, h.manifold->objective);
        }
        s = h.result;
      }
      const double cpu = bench::cpu_seconds() - cpu0;
      cpu_total += cpu;
      const bench::IndependentStationarity r = bench::independent_stationarity(problem, s.x, kKinkEps, kActive);
      const bool at_kkt = r.evaluated && r.violation <= kFeasible && r.sample_box <= kStationary;
      stationary += at_kkt;
      const bool feasible = r.evaluated && r.violation <= kFeasible;
      within_1e4 += feasible && r.sample_box <= 1e-4;
      within_1e3 += feasible && r.sample_box <= 1e-3;
      converged += s.termination == nlp::Termination::converged;
      if (at_kkt) best = std::min(best, s.objective);
      std::printf("  %3d  %-14s %-14s %5d  %.8f  %.1e  %.1e     %.1e     %.1e       %4d     %.2f%s\n", i,
                  nlp::to_string(s.termination), nlp::to_string(s.optimality), s.iterations, s.objective, r.violation,
                  s.kkt_error, r.sample_box, r.interval_box, r.samples_at_kink, cpu, at_kkt ? "" : "  (not stationary)");
      if (!s.success()) std::printf("       %s\n", s.message.substr(0, 160).c_str());
    }
    std::printf("%s: %d/%d at a (nonsmooth) KKT point by the independent residual (feasible, residual <= 1e-6; <= 1e-4: %d, "
                "<= 1e-3: %d), %d/%d converged by the solver's test, best such f_mech %.8f; CPU %.1f s for the %d runs; %s\n",
                name.c_str(), stationary, starts, within_1e4, within_1e3, converged, starts, best, cpu_total, starts,
                bench::load_average().c_str());
  }
}
