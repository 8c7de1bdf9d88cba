// Issue 15, acceptance 2 and 3: the foot-design study of seed 001 section 10.2
// (studies/foot_design.hpp) from P2-shoes-left-HMT: per density the design multistart at the
// design speed, the free-foot continuation over the grid and the fixed-foot sweeps of the feet
// optimal at the highest and lowest speed, against the start foot (its own masses) and point feet.
// Prints per density the design, its active bounds (10.1), the classes of the optima, the time
// per phase, and ends each block with the figures of the density's answer (the better of its two
// fixed-foot designs, studies::better_design)
//   rho R: saving vs start S %, vs point feet Q %, speeds N/21, wall T s
// Each block is printed as soon as its density ends (a long list stopped early keeps what it found).
//
// usage: foot_design_bench [densities = 10] [starts = 20] [speeds = 0.3:0.1:2.3] [sweep_starts = 4]
//        [dominance_starts = 0] [band = 0]
//   densities: comma-separated; speeds: FROM:STEP:TO (the design speed is the last); dominance_starts:
//   SpeedSweepOptions::dominance_starts of every sweep (0: sweep_starts); band: the positive_power_band
//   of f_mech (W, walker/positive_power.hpp) of every solve
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/service/value_range.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/studies/foot_design.hpp"
#include "machine_info.hpp"
#include "recovery_lines.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace cyclopt;

namespace {

std::vector<double> list(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) out.push_back(std::stod(item));
  return out;
}

// The service's grid ("0.3:0.1:2.3" holds 0.6, the double of "0.6"), so that this study solves what a
// foot_design job of the same speeds solves.
std::vector<double> grid(const std::string& text) {
  try {
    return service::parse_value_range(text, "speeds", jobs::kMinWalkingSpeed, jobs::kMaxWalkingSpeed);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "%s\n", e.what());
    std::exit(1);
  }
}

// Its speeds and mean f_mech, how many of its points are only "acceptable" (a step below TolStep,
// no KKT test passed: acceptance 2 asks for a KKT point at every speed), and at which speeds the
// point is under-resolved (f_mech on the 4x finer grid more than 10 % away, design_class.hpp).
void print_sweep(const studies::FootSweepSummary& s, const walker::WalkerModel<double>& model) {
  double sum = 0.0;
  for (double f : s.f_mech)
    if (std::isfinite(f)) sum += f;
  int acceptable = 0;
  std::string under_resolved;
  for (const studies::BestPoint& b : s.best) {
    if (!b.found) continue;
    if (b.point.corrector.termination == nlp::Termination::acceptable) ++acceptable;
    const walker::GaitProblem at(model, {walker::Objective::mechanical, b.speed, walker::Quadrature::trapezoid, {}});
    const double fine = at.refined_objective(b.point.x, studies::kResolutionFactor);
    if (!studies::resolved(b.point.objective, fine)) {
      char buf[64];
      std::snprintf(buf, sizeof buf, " %.2g (%.4f -> %.4f)", b.speed, b.point.objective, fine);
      under_resolved += buf;
    }
  }
  std::printf("  %-28s speeds %2d/%zu (%d only acceptable; under-resolved:%s), mean f_mech %.5f over them, %.1f s:",
              s.name.c_str(), s.speeds_found, s.f_mech.size(), acceptable, under_resolved.empty() ? " none" : under_resolved.c_str(),
              s.speeds_found ? sum / s.speeds_found : std::nan(""), s.seconds);
  for (double f : s.f_mech) std::printf(" %.4f", f);
  std::printf("\n");
  bench::print_recoveries(s.recoveries, "    ");
}

// The foot's parameters on the current line: "name value" per parameter of its layout.
void print_parameters(const foot::FootSpec& f) {
  const auto layout = foot::parameter_layout(f.model);
  for (std::size_t k = 0; k < layout.size(); ++k)
    std::printf(" %s %.4g", std::string(layout[k].name).c_str(), f.parameters[static_cast<Eigen::Index>(k)]);
}

// One density's block, ending with the line of acceptance 2.
void print_density(const studies::DensityDesign& d, int starts, std::size_t n, const walker::WalkingConstants& constants) {
  std::printf("rho %.4g kg/m^2: %d/%d design starts KKT, %zu distinct optima (admissible %d, stilt %d, wheel %d, no rolling %d, "
              "under-resolved %d)\n",
              d.density, d.kkt_starts, starts, d.optima.size(), d.class_counts[0], d.class_counts[1], d.class_counts[2],
              d.class_counts[3], d.class_counts[4]);
  for (std::size_t k = 0; k < d.runs.size(); ++k)
    std::printf("  start %2zu: %-18s %5d iterations %6d evaluations %6.1f s  f %.5f\n", k,
                nlp::to_string(d.runs[k].termination), d.runs[k].iterations, d.runs[k].evaluations, d.runs[k].seconds,
                d.runs[k].objective);
  for (std::size_t k = 0; k < d.optima.size(); ++k) {
    const studies::DesignOptimum& m = d.optima[k];
    std::printf("  optimum %zu: f %.5f, %s (%s)\n", k, m.objective, studies::to_string(m.classification.design_class),
                m.classification.reason.c_str());
  }
  if (d.best >= 0) {
    const studies::DesignOptimum& b = d.optima[static_cast<std::size_t>(d.best)];
    std::printf("  design (optimum %d):", d.best);
    print_parameters(b.foot);
    std::printf("\n  m_F %.3f kg, r_F %.1f mm, J_F %.2e kg m^2, theta_F0 %.3f rad; active bounds (10.1):", b.mass,
                1e3 * b.com_distance, b.inertia, b.zero_angle);
    for (const std::string& a : b.active_bounds) std::printf(" [%s]", a.c_str());
    std::printf("\n  free-foot continuation: %zu points, %s; f_mech per speed:", d.free_foot.points.size(), d.free_foot.message.c_str());
    for (double f : d.free_foot_f_mech) std::printf(" %.4f", f);
    std::printf("\n  low-speed design at %.2f m/s:", d.low_speed);
    print_parameters(d.low_speed_foot);
    std::printf("\n");
    print_sweep(d.high, walker::make_walker_model(b.foot, constants));
    print_sweep(d.low, walker::make_walker_model(d.low_speed_foot, constants));
    std::printf("  low-speed design: saving vs start %.1f %%, vs point feet %.1f %%\n", 100 * d.low_saving_vs_start,
                100 * d.low_saving_vs_point);
  }
  std::printf("  phases: design multistart %.1f s, free-foot continuation %.1f s, fixed-foot sweeps %.1f s after it"
              " (the design's %.1f s from the start of the continuation, the low-speed design's %.1f s)\n",
              d.multistart_seconds, d.continuation_seconds, d.sweep_seconds, d.high.seconds, d.low.seconds);
  std::printf("  answer: the %s (studies::better_design)\n", studies::to_string(d.answer));
  std::printf("rho %.4g: saving vs start %.1f %%, vs point feet %.1f %%, speeds %d/%zu, wall %.1f s\n", d.density,
              100 * d.answer_saving_vs_start(), 100 * d.answer_saving_vs_point(), d.answer_sweep().speeds_found, n,
              d.seconds);
}

}  // namespace

int main(int argc, char** argv) {
  studies::FootDesignOptions o;
  o.densities = list(argc > 1 ? argv[1] : "10");
  o.starts = argc > 2 ? std::atoi(argv[2]) : 20;
  o.sweep.speeds = grid(argc > 3 ? argv[3] : "0.3:0.1:2.3");
  o.sweep.starts = argc > 4 ? std::atoi(argv[4]) : 4;
  if (argc > 5) o.sweep.dominance_starts = std::atoi(argv[5]);
  o.design_speed = o.sweep.speeds.back();
  walker::GaitProblemOptions problem{walker::Objective::mechanical, o.design_speed, walker::Quadrature::trapezoid, {}};
  if (argc > 6) problem.positive_power_band = std::atof(argv[6]);
  std::printf("foot_design_bench on %s\n", bench::machine_line().c_str());
  std::printf("start foot P2-shoes-left-HMT, design speed %.2f m/s, %d design starts, %zu speeds, %d starts per sweep"
              " (%d in its dominance tests), positive-power band %g W\n",
              o.design_speed, o.starts, o.sweep.speeds.size(), o.sweep.starts,
              o.sweep.dominance_starts > 0 ? o.sweep.dominance_starts : o.sweep.starts, problem.positive_power_band);
  // Each result is printed as soon as it is known, so a long list leaves every finished density.
  // Prints the steps, the references and each density's result as they end.
  class Printer final : public studies::FootDesignObserver {
   public:
    Printer(const studies::FootDesignOptions& o, std::chrono::steady_clock::time_point started)
        : o_(o), started_(started) {}
    bool on_step(const std::string& step) override {
      std::printf("-- %s\n", step.c_str());
      std::fflush(stdout);
      return true;
    }
    bool on_reference(const std::string& part, const walker::WalkerModel<double>& model,
                      const studies::FootSweepSummary& s) override {
      const bool point = part == studies::reference_part(studies::DesignReference::point_feet);
      (point ? point_feet_ : start_foot_) = s;
      if (!point) {
        start_model_ = model;
      } else {  // the second and last reference
        std::printf("references (%.1f s):\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count());
        print_sweep(start_foot_, *start_model_);
        print_sweep(point_feet_, model);
        std::fflush(stdout);
      }
      return true;
    }
    bool on_density(const studies::DensityDesign& so_far, studies::DesignPhase finished) override {
      if (finished == studies::DesignPhase::low_sweep || (finished == studies::DesignPhase::multistart && so_far.best < 0)) {
        studies::DensityDesign d = so_far;
        studies::add_savings(d, o_.sweep.speeds, start_foot_, point_feet_);
        print_density(d, o_.starts, o_.sweep.speeds.size(), o_.constants);
        std::fflush(stdout);
      }
      return true;
    }

   private:
    const studies::FootDesignOptions& o_;
    const std::chrono::steady_clock::time_point started_;
    studies::FootSweepSummary start_foot_, point_feet_;
    std::optional<walker::WalkerModel<double>> start_model_;
  } printer(o, std::chrono::steady_clock::now());
  const foot::FootSpec start = foot::foot_preset("P2-shoes-left-HMT").spec;
  studies::FootDesignResult r;
  try {
    r = studies::design_feet(start, problem, o, printer);
  } catch (const std::invalid_argument& e) {  // options the study refuses, named by their field
    std::fprintf(stderr, "foot_design_bench: %s\n", e.what());
    return 2;
  }
  std::printf("total %.1f s (references %.1f s)\n", r.seconds, r.reference_seconds);
}
