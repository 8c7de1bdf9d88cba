// Speed against error of the semi-analytic periodic gait (seed 001 sections 5.2.4-5.4), issue 3:
// for a reference gait of each foot model (HM P1 barefoot Tab. 4.2, HMT P2 shoes Tab. B.9, point
// feet Tab. D.1; the automatic starting gait at 1.3 m/s) and P = 25 ... 3200 grid points: time per
// evaluation (values; values + Jacobian by forward-mode AD) and the relative errors of f_mech,
// f_usq, the step period and Lambda against a converged reference (corrected trapezoid, P = 51200),
// for the seed's cumulative trapezoid rule and the Euler-Maclaurin corrected one.
//
// walker_bench --jacobian: only P = 200 (trapezoid), value and value + Jacobian by the evaluator's
// path and by the reference path (chunks of Dual<8>, model cast to Dual), best of 5 repeats, and
// the largest difference between the two Jacobians relative to the largest entry of its row.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/walker/starting_gait.hpp"
#include "machine_info.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>

using namespace cyclopt;
using namespace cyclopt::walker;
using Clock = std::chrono::steady_clock;

namespace {

template <class F>
double seconds_per_call(F&& f, double budget) {
  int calls = 0;
  const auto t0 = Clock::now();
  double elapsed = 0.0;
  do {
    f();
    ++calls;
    elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
  } while (elapsed < budget);
  return elapsed / calls;
}

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

template <class F>
double best_of(int repeats, F&& f, double budget) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) best = std::min(best, seconds_per_call(f, budget));
  return best;
}

// Largest |J_a - J_b| of a row relative to the row's largest |J_b| entry, over all rows.
double row_relative_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  double worst = 0.0;
  for (int r = 0; r < a.rows(); ++r) {
    const double scale = b.row(r).cwiseAbs().maxCoeff();
    if (scale > 0.0) worst = std::max(worst, (a.row(r) - b.row(r)).cwiseAbs().maxCoeff() / scale);
  }
  return worst;
}

int jacobian_timings() {
  std::printf("walker_bench --jacobian on %s\n", cyclopt::bench::machine_line().c_str());
  std::printf("P = 200, trapezoid, automatic starting gait at 1.3 m/s; best of 5 repeats (ms)\n");
  std::printf("%-20s %4s %10s %14s %16s %14s\n", "foot", "n_x", "value", "+Jacobian", "+Jacobian (ref)",
              "max row diff");
  for (const char* name : {"point", "P1-barefoot-left-HM", "P2-shoes-left-HMT"}) {
    const GaitEvaluator ev(make_walker_model(foot::foot_preset(name).spec));
    const StartingGait start = starting_gait(ev, StartingGaitOptions{});
    GaitOptions opt;
    opt.keep_trajectories = false;
    const double tv = best_of(5, [&] { ev.evaluate(start.x, opt); }, 0.2);
    const double tj = best_of(5, [&] { ev.evaluate_with_derivatives(start.x, opt); }, 0.3);
    const double tr = best_of(5, [&] { ev.evaluate_with_reference_derivatives(start.x, opt); }, 0.3);
    const double diff = row_relative_difference(ev.evaluate_with_derivatives(start.x, opt).derivatives.stacked(),
                                                ev.evaluate_with_reference_derivatives(start.x, opt).derivatives.stacked());
    std::printf("%-20s %4d %10.4f %14.3f %16.3f %14.2e\n", name, static_cast<int>(start.x.size()), tv * 1e3, tj * 1e3,
                tr * 1e3, diff);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--jacobian") == 0) return jacobian_timings();
  std::printf("walker_bench on %s\n", cyclopt::bench::machine_line().c_str());
  std::printf("reference gaits: automatic starting gait at 1.3 m/s (starting_gait.hpp); errors relative to P = 51200, "
              "corrected trapezoid\n\n");
  for (const char* name : {"P1-barefoot-left-HM", "P2-shoes-left-HMT", "point"}) {
    const foot::FootSpec spec = foot::foot_preset(name).spec;
    const StartingGait start = starting_gait(GaitEvaluator(make_walker_model(spec)), StartingGaitOptions{});
    auto evaluator = [&](int P) {
      WalkingConstants c;
      c.points = P;
      return GaitEvaluator(make_walker_model(spec, c));
    };
    GaitOptions opt;
    opt.keep_trajectories = false;
    opt.quadrature = Quadrature::corrected_trapezoid;
    const PeriodicGait<double> ref = evaluator(51200).evaluate(start.x, opt);
    std::printf("%s: f_mech %.8f, f_usq %.6f, period %.8f s, Lambda %.8f (%d gait parameters)\n", name, ref.f_mech,
                ref.f_usq, ref.step_period, ref.floquet, static_cast<int>(start.x.size()));
    std::printf("%6s %-10s %12s %14s %10s %10s %10s %10s\n", "P", "rule", "value (ms)", "+Jacobian (ms)", "err f_mech",
                "err f_usq", "err period", "err Lambda");
    for (int P : {25, 50, 100, 200, 400, 800, 1600, 3200})
      for (Quadrature q : {Quadrature::trapezoid, Quadrature::corrected_trapezoid}) {
        const GaitEvaluator ev = evaluator(P);
        opt.quadrature = q;
        const PeriodicGait<double> g = ev.evaluate(start.x, opt);
        if (!g.real) {
          std::printf("%6d %-10s %s\n", P, q == Quadrature::trapezoid ? "trapezoid" : "corrected", g.failure.c_str());
          continue;
        }
        const double tv = seconds_per_call([&] { ev.evaluate(start.x, opt); }, 0.2);
        const double tj = seconds_per_call([&] { ev.evaluate_with_derivatives(start.x, opt); }, 0.3);
        std::printf("%6d %-10s %12.4f %14.3f %10.2e %10.2e %10.2e %10.2e\n", P,
                    q == Quadrature::trapezoid ? "trapezoid" : "corrected", tv * 1e3, tj * 1e3, rel(g.f_mech, ref.f_mech),
                    rel(g.f_usq, ref.f_usq), rel(g.step_period, ref.step_period), rel(g.floquet, ref.floquet));
      }
    std::printf("\n");
  }
}
