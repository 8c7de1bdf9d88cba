// The chapter-9 workflow of seed 001 (Fig. 9.7) as a benchmark: multistart at 0.3, 1.3 and
// 2.3 m/s, QPSQP continuation of the best optima both ways over 0.3:0.1:2.3 m/s and of every
// curve jumped to, best point per speed. Printed: wall time (multistart and total), the curves
// with their speed ranges, the jumps, and per grid speed the selected curve and f_mech (or why
// none), and how far each best f_mech is from its gait's value on a 64x finer grid (the corrected
// rule): the discretisation error the sweep's speed is bought with. Issue 5 asks for
// <= 60 s wall per foot model.
//
// usage: speed_sweep_bench [foot = point] [starts = 4] [budget_seconds = 600] [recover|plain] [P = 200]
// [trapezoid|corrected] [coarse P = 100; SpeedSweepOptions::coarse_points, 0 off] [qp|qp-per-try|trivial|trivial_then_qp
// predictor] [dominance starts = 0; SpeedSweepOptions::dominance_starts, 0 = starts] [band W = 0;
// GaitProblemOptions::positive_power_band]:
// foot is a preset name or a JSON foot file (bench/feet/); qp-per-try computes the predictor's difference Hessians
// per try as Algorithm 2 (ContinuationOptions::reuse_predictor_hessian false), trivial gives the corrector W_1 of
// (6.24); the sweep is stopped at
// the first point after the budget (then the per-speed table shows what was reached); "plain" switches the
// recovery (R1-R3) off. Options anywhere on the line: --seeds=1,2,3 (one search per seed,
// SpeedSweepOptions::seeds; default 1), --closure=N (passes at most of the envelope closure, 0 off; default 8),
// --kinks (every solve of the sweep - multistarts and correctors - with f_mech's kinks modelled,
// nlp::KinkOptions, issue 52), --seed-speeds=0.3,0.5,1.3,2.3 (SpeedSweepOptions::seed_speeds),
// --max-curves=N (SpeedSweepOptions::max_curves, per search).
#include "bench_foot.hpp"
#include "cyclopt/service/value_range.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/studies/speed_sweep.hpp"
#include "machine_info.hpp"
#include "recovery_lines.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <map>
#include <vector>
#include <string>

using namespace cyclopt;
using namespace cyclopt::continuation;
using namespace cyclopt::studies;

namespace {

// Every best gait evaluated again at its speed on a grid kFineFactor times finer (the corrected
// rule; its own error is ~1e-9): per speed and the mean relative error of the sweep's f_mech.
constexpr int kFineFactor = 64;

void print_fine_grid_errors(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& po,
                            const SpeedSweepResult& r) {
  double sum = 0.0, sum_error = 0.0, worst = 0.0, worst_speed = 0.0;
  int n = 0;
  std::printf("\nthe best gaits on a fine grid (P = %d, corrected rule):\n", (model.constants.points - 1) * kFineFactor + 1);
  for (const BestPoint& b : r.best) {
    if (!b.found) continue;
    walker::GaitProblemOptions fo = po;
    fo.speed = b.speed;
    fo.quadrature = walker::Quadrature::corrected_trapezoid;
    fo.positive_power_band = 0.0;
    const double fine = walker::GaitProblem(model, fo).refined_objective(b.point.x, kFineFactor);
    if (!std::isfinite(fine)) {
      std::printf("  %.1f m/s: no real gait on the fine grid\n", b.speed);
      continue;
    }
    const double error = std::abs(b.point.objective - fine) / std::abs(fine);
    std::printf("  %.1f m/s: f_mech %.6f (sweep's grid %.6f, relative error %.1e)\n", b.speed, fine, b.point.objective, error);
    sum += fine;
    sum_error += error;
    ++n;
    if (error > worst) {
      worst = error;
      worst_speed = b.speed;
    }
  }
  if (n > 0)
    std::printf("fine-grid mean f_mech %.6f over %d speeds; the sweep's f_mech: mean relative error %.1e, worst %.1e "
                "at %.1f m/s\n", sum / n, n, sum_error / n, worst, worst_speed);
}

// "1,2,3" -> {1, 2, 3}
template <class T, class Parse>
std::vector<T> comma_list(const std::string& text, Parse parse) {
  std::vector<T> values;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t comma = text.find(',', at);
    values.push_back(parse(text.substr(at, comma - at)));
    at = comma == std::string::npos ? text.size() : comma + 1;
  }
  return values;
}

}  // namespace

int main(int argc_in, char** argv_in) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  // --seeds=, --seed-speeds=, --closure=, --max-curves= and --kinks anywhere; the rest are positional.
  std::vector<char*> positional;
  std::vector<std::uint64_t> seeds{1};
  std::vector<double> seed_speeds = SpeedSweepOptions{}.seed_speeds;
  int closure_passes = EnvelopeClosureOptions{}.max_passes;
  int max_curves = SpeedSweepOptions{}.max_curves;
  bool kinks = false;
  for (int i = 0; i < argc_in; ++i) {
    const std::string a = argv_in[i];
    if (a.rfind("--seeds=", 0) == 0) {
      seeds = comma_list<std::uint64_t>(a.substr(8), [](const std::string& t) { return std::stoull(t); });
    } else if (a.rfind("--seed-speeds=", 0) == 0) {
      seed_speeds = comma_list<double>(a.substr(14), [](const std::string& t) { return std::stod(t); });
    } else if (a.rfind("--closure=", 0) == 0) {
      closure_passes = std::atoi(a.c_str() + 10);
    } else if (a.rfind("--max-curves=", 0) == 0) {
      max_curves = std::atoi(a.c_str() + 13);
    } else if (a == "--kinks") {
      kinks = true;
    } else {
      positional.push_back(argv_in[i]);
    }
  }
  const int argc = static_cast<int>(positional.size());
  char** argv = positional.data();
  const std::string foot_name = argc > 1 ? argv[1] : "point";
  const int starts = argc > 2 ? std::atoi(argv[2]) : 4;
  const double budget = argc > 3 ? std::atof(argv[3]) : 600.0;
  const auto t0 = std::chrono::steady_clock::now();
  std::printf("speed_sweep_bench on %s, %s at the start\n", bench::machine_line().c_str(), bench::load_average().c_str());
  walker::WalkingConstants constants;
  if (argc > 5) constants.points = std::atoi(argv[5]);
  const walker::WalkerModel<double> model = walker::make_walker_model(bench::bench_foot(foot_name), constants);
  const double cpu_at_start = bench::cpu_seconds();
  const walker::Quadrature rule =
      argc > 6 && std::string(argv[6]) == "corrected" ? walker::Quadrature::corrected_trapezoid : walker::Quadrature::trapezoid;
  walker::GaitProblemOptions po{walker::Objective::mechanical, 1.3, rule, {}};
  if (argc > 10) po.positive_power_band = std::atof(argv[10]);
  SpeedSweepOptions o;
  // The service's grid (0.3, 0.4, ..., 2.3 as typed), so that this sweep solves what a job solves.
  o.speeds = service::parse_value_range("0.3:0.1:2.3", "speeds", jobs::kMinWalkingSpeed, jobs::kMaxWalkingSpeed);
  o.starts = starts;
  o.recover = !(argc > 4 && std::string(argv[4]) == "plain");
  o.seeds = seeds;
  o.seed_speeds = seed_speeds;
  o.max_curves = max_curves;
  std::printf("seed speeds (multistart):");
  for (double v : seed_speeds) std::printf(" %.2f", v);
  std::printf(" m/s; at most %d curves per search\n", max_curves);
  o.closure.enabled = closure_passes > 0;
  o.closure.max_passes = std::max(closure_passes, 1);
  if (argc > 7) o.coarse_points = std::atoi(argv[7]);
  if (argc > 8 && std::string(argv[8]) == "qp-per-try")  // the QP predictor with two (6.24) per try (Algorithm 2)
    o.continuation.reuse_predictor_hessian = false;
  else if (argc > 8)
    o.continuation.predictor = parse_predictor(argv[8]);
  if (argc > 9) o.dominance_starts = std::atoi(argv[9]);
  o.continuation.corrector.sqp.kinks.enabled = kinks;  // the multistarts' solver is built from the corrector's
  // The trivial predictor hands the corrector no W: it starts from W_1 of (6.24), as in continuation_bench.
  if (o.continuation.predictor == continuation::Predictor::trivial) o.continuation.corrector.sqp.difference_hessian = true;
  const SpeedSweepResult r = speed_sweep(model, po, o, [&](const CurvePoint& p) {
    std::printf("  point v %.4f curve %d %s f %.6f (%d corrector iterations, %.2f s)\n", p.parameter, p.curve_id,
                p.converged ? "ok    " : "FAILED", p.objective, p.corrector.iterations, p.seconds);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < budget;
  });
  std::printf("\nfoot %s, f_mech (positive-power band %g W), P = %d (multistarts at P = %d first), %s rule, %d multistart runs per seed speed: %d curves, %zu continuation runs\n",
              foot_name.c_str(), po.positive_power_band, constants.points, o.coarse_points > 0 ? o.coarse_points : constants.points,
              rule == walker::Quadrature::trapezoid ? "trapezoid" : "corrected", starts, r.curves, r.runs.size());
  std::printf("continuation: %s predictor, predictor Hessian %s; dominance tests' R2 with %d perturbations; f_mech's kinks %s\n",
              to_string(o.continuation.predictor), predictor_hessian_name(o.continuation.reuse_predictor_hessian),
              o.dominance_starts > 0 ? o.dominance_starts : o.starts, kinks ? "modelled (--kinks)" : "not modelled");
  // Idle estimate: the multistarts use both cores, the continuation runs one.
  const double cpu = bench::cpu_seconds() - cpu_at_start;
  std::printf("wall time %.1f s (multistart %.1f s for %d solves, recovery %.1f s), %s at the end\n", r.seconds,
              r.multistart_seconds, r.multistart_solves, r.recovery_seconds, bench::load_average().c_str());
  std::printf("CPU %.1f s user+sys (multistart %.1f s, the rest %.1f s): idle-machine wall estimate %.1f s\n", cpu,
              r.multistart_cpu_seconds, cpu - r.multistart_cpu_seconds,
              r.multistart_cpu_seconds / 2.0 + cpu - r.multistart_cpu_seconds);
  for (const ContinuationResult& run : r.runs) {
    std::printf("run %.2f -> %.2f: %zu points, %d corrector iterations, %.1f s, %s\n", run.points.front().parameter,
                run.points.back().parameter, run.points.size(), run.corrector_iterations, run.seconds, run.message.c_str());
    for (const CurveJump& j : run.jumps)
      std::printf("  jump curve %d -> %d between v = %.4f and %.4f: f %.6f -> %.6f\n", j.from_curve, j.to_curve,
                  j.from_parameter, j.to_parameter, j.objective_before, j.objective_after);
  }
  bench::print_recoveries(r.recoveries);
  std::printf("\nbest per speed:\n");
  // A point counts as a KKT point only if its solve converged; the sweep also takes the SQP's
  // "acceptable" stop (a step below TolStep while feasible: a potential KKT point), named here.
  int kkt = 0, acceptable = 0;
  for (const BestPoint& b : r.best) {
    const bool converged = b.found && b.point.corrector.termination == nlp::Termination::converged;
    kkt += converged;
    acceptable += b.found && !converged;
    if (b.found)
      std::printf("  %.1f m/s: curve %d, f_mech %.6f, %s (%s)\n", b.speed, b.point.curve_id, b.point.objective,
                  nlp::to_string(b.point.corrector.termination), describe(b).c_str());
    else
      std::printf("  %.1f m/s: none (%s)\n", b.speed, b.reason.c_str());
  }
  std::printf("%d/%zu speeds with a KKT point, %d more with an acceptable point only\n", kkt, r.best.size(), acceptable);
  std::printf("closure: %s, %d solves, %.1f s\n", describe(r.closure).c_str(), r.closure.solves, r.closure.seconds);
  double mean = 0.0;
  int found = 0;
  for (const BestPoint& b : r.best)
    if (b.found) mean += b.point.objective, ++found;
  std::printf("mean f over %d speeds: %.6f (the envelope of %zu search%s)\n", found, found ? mean / found : 0.0, r.searches.size(),
              r.searches.size() == 1 ? "" : "es");
  if (r.searches.size() > 1) {
    std::vector<double> means;
    for (const SeedSearch& s : r.searches) {
      double m = 0.0;
      int k = 0;
      for (const BestPoint& b : s.best)
        if (b.found) m += b.point.objective, ++k;
      means.push_back(k ? m / k : 0.0);
      std::printf("  seed %llu: mean f %.6f over %d speeds, %s, %.1f s\n", static_cast<unsigned long long>(s.seed), means.back(), k,
                  describe(s.closure).c_str(), s.seconds);
    }
    std::printf("spread of the seeds' means (max - min) / min: %.2f %%\n",
                100.0 * (*std::max_element(means.begin(), means.end()) / *std::min_element(means.begin(), means.end()) - 1.0));
    std::printf("per speed spread between the seeds' envelopes:");
    for (std::size_t i = 0; i < r.seed_spread.size(); ++i) std::printf(" %.1f:%.1f%%", r.best[i].speed, 100.0 * r.seed_spread[i]);
    std::printf("\n");
  }
  print_fine_grid_errors(model, po, r);
  return 0;
}
