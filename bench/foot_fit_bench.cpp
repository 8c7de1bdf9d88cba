// Issue 20 acceptance 1 and 3: the seed's fits (section 4.2) on synthetic trials of every
// catalogue foot: three trials at 200 Hz with 0.5 mm marker noise. Per foot and fit: recovery
// of the lengths and gamma_F within 4 standard errors (the covariance sigma^2 (J^T J)^-1 of the
// fit, i.e. a tolerance derived from the noise), the RMS residual against its expectation at
// that noise, HMT never worse than HM, and the time per fit with the number of samples.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot_fit/ankle_track.hpp"
#include "cyclopt/foot_fit/rolling_foot_fit.hpp"
#include "cyclopt/foot_fit/synthetic_trials.hpp"
#include "machine_info.hpp"

#include <cmath>
#include <cstdlib>
#include <exception>
#include <cstdio>
#include <string>
#include <vector>

namespace cf = cyclopt::foot_fit;
namespace foot = cyclopt::foot;

namespace {

constexpr double kMarkerNoise = 0.0005;  // m per marker coordinate
constexpr double kTolerance = 4.0;       // standard errors

std::vector<cf::AnkleTrack> trials(const foot::FootSpec& f, double rate, std::uint64_t seed) {
  std::vector<cf::AnkleTrack> tracks;
  for (int k = 0; k < 3; ++k) {
    cf::SyntheticTrialOptions o;
    o.rate = rate;
    o.noise = kMarkerNoise;
    o.offset = 0.4 + 0.11 * k;
    o.walking_direction = 0.02 * k;
    o.seed = seed + k;
    o.foot_angle = cf::default_foot_angle_history(f);
    for (auto& knot : o.foot_angle) knot.t *= 1.0 + 0.07 * k;
    tracks.push_back(cf::ankle_track(cf::synthetic_trial(f, o)));
  }
  return tracks;
}

// The seed's bounds, widened where the generating foot itself lies outside them.
cf::FootFitOptions options_for(const foot::FootSpec& f, double z_min, std::string& note) {
  cf::FootFitOptions o;
  const cf::FitBounds seed = cf::seed_bounds(f.model, z_min);
  const cf::FitBounds b = cf::widened_to_contain(seed, f.parameters);
  for (Eigen::Index i = 0; i < b.upper.size(); ++i)
    if (b.upper[i] != seed.upper[i] || b.lower[i] != seed.lower[i])
      note.append(" ").append(foot::parameter_layout(f.model)[i].name).append(" outside the seed bound (widened)");
  (f.model == foot::FootModel::hm ? o.hm_bounds : o.hmt_bounds) = b;
  return o;
}

}  // namespace

// Usage: foot_fit_bench [STRIDE]: every STRIDE-th catalogue foot (default 1: all 216).
int main(int argc, char** argv) {
  const int stride = argc > 1 ? std::max(1, std::atoi(argv[1])) : 1;
  std::printf("foot_fit_bench on %s, %s at start\n", cyclopt::bench::machine_line().c_str(), cyclopt::bench::load_average().c_str());
  std::printf("synthetic trials: 3 per foot, 200 Hz, marker noise %.2f mm per coordinate (ankle = mean of two markers: "
              "%.3f mm per coordinate)\n",
              1e3 * kMarkerNoise, 1e3 * kMarkerNoise / std::sqrt(2.0));
  std::printf("tolerance: |fitted - true| <= %.0f standard errors of the fit; RMS ratio = RMS / (sigma_A sqrt((2N - n)/N))\n\n",
              kTolerance);
  std::printf("%-24s %-4s %5s %9s %9s %7s %7s %10s %s\n", "foot", "fit", "N", "RMS/mm", "max/mm", "ratio", "t/s",
              "worst/SE", "recovered / notes");
  int feet = 0, skipped = 0, recovered = 0, rms_ok = 0, hmt_not_worse = 0, converged = 0, fits = 0;
  double worst_hm_time = 0, worst_hmt_time = 0;
  const double sigma_a = kMarkerNoise / std::sqrt(2.0);
  int index = -1, failed = 0;
  for (const foot::FootPreset& preset : foot::foot_presets()) {
    const foot::FootSpec& truth = preset.spec;
    if (truth.model == foot::FootModel::point) continue;
    if (++index % stride != 0) continue;
    if (preset.fitted && !preset.fitted->flag.empty()) {
      ++skipped;
      std::printf("%-24s skipped: %s\n", preset.name.c_str(), preset.fitted->flag.c_str());
      continue;
    }
    ++feet;
    std::fflush(stdout);
    std::vector<cf::AnkleTrack> tracks;
    cf::CircleFitStart start;
    try {
      tracks = trials(truth, 200.0, 1000 + 10 * feet);
      start = cf::circle_fit_start(tracks);
    } catch (const std::exception& e) {
      ++failed;
      std::printf("%-24s FAILED: %s\n", preset.name.c_str(), e.what());
      continue;
    }
    std::string note;
    const cf::FootFitOptions options = options_for(truth, start.z_min, note);
    const cf::FootFitResult hm = cf::fit_hm(tracks, start, options);
    const cf::FootFitResult hmt = cf::fit_hmt(tracks, hm, start.z_min, options);
    worst_hm_time = std::max(worst_hm_time, hm.seconds);
    worst_hmt_time = std::max(worst_hmt_time, hmt.seconds);
    const bool not_worse = hmt.rms <= hm.rms * (1.0 + 1e-9);
    hmt_not_worse += not_worse ? 1 : 0;
    for (const cf::FootFitResult* f : {&hm, &hmt}) {
      ++fits;
      converged += f->converged ? 1 : 0;
      const double expected = sigma_a * std::sqrt(double(2 * f->samples - f->unknowns) / f->samples);
      const double ratio = f->rms / expected;
      std::string verdict = f->converged ? "" : " NOT CONVERGED (" + f->message + ")";
      double worst = 0.0;
      if (f->model == truth.model) {
        bool ok = true;
        const auto layout = foot::parameter_layout(truth.model);
        for (std::size_t i = 0; i < layout.size(); ++i) {
          if (layout[i].name.rfind("k_", 0) == 0) continue;  // the lengths and gamma_F
          const double err = std::abs(f->parameters[i] - truth.parameters[i]);
          const double se = f->estimates[i].standard_error;
          worst = std::max(worst, err / se);
          if (!(err <= kTolerance * se)) {
            ok = false;
            char buf[120];
            std::snprintf(buf, sizeof buf, " %s off by %.3g mm = %.1f SE", std::string(layout[i].name).c_str(), 1e3 * err, err / se);
            verdict += buf;
          }
        }
        recovered += ok ? 1 : 0;
        rms_ok += (ratio > 0.85 && ratio < 1.15) ? 1 : 0;
        verdict = (ok ? "yes" : "NO") + verdict;
      } else {
        verdict = "(other model)" + verdict;
      }
      std::printf("%-24s %-4s %5d %9.4f %9.4f %7.3f %7.4f %10.2f %s%s%s\n", preset.name.c_str(),
                  std::string(foot::to_string(f->model)).c_str(), f->samples, 1e3 * f->rms, 1e3 * f->max_residual, ratio,
                  f->seconds, worst, verdict.c_str(), f == &hmt && !not_worse ? " HMT WORSE THAN HM" : "",
                  f == &hm ? note.c_str() : "");
    }
  }
  std::printf("\nfeet %d (every %d-th catalogue preset; %d skipped as not admissible or not convex; %d without a start)%s\n",
              feet, stride, skipped, failed,
              feet < 20 ? " -- FEWER THAN THE 20 OF ACCEPTANCE 1" : "");
  std::printf("recovered within %.0f SE (own model): %d of %d; RMS ratio in (0.85, 1.15): %d of %d; HMT not worse than HM: %d of %d; "
              "converged: %d of %d fits\n",
              kTolerance, recovered, feet, rms_ok, feet, hmt_not_worse, feet, converged, fits);
  std::printf("slowest fit at N = 3 trials x ~125 samples: HM %.4f s, HMT %.4f s\n\n", worst_hm_time, worst_hmt_time);

  // Acceptance 3: time per fit against the number of samples (one foot, three trials).
  std::printf("time per fit against samples (P2-shoes-left-HMT, 3 trials, rate varied), %s\n", cyclopt::bench::load_average().c_str());
  std::printf("%8s %7s %10s %10s %8s %8s %10s\n", "rate/Hz", "N", "HM t/s", "HMT t/s", "HM it", "HMT it", "CPU s");
  const foot::FootSpec p2 = foot::foot_preset("P2-shoes-left-HMT").spec;
  for (double rate : {200.0, 1000.0, 2000.0, 4000.0}) {
    const auto tracks = trials(p2, rate, 7);
    const double cpu0 = cyclopt::bench::cpu_seconds();
    const cf::CircleFitStart start = cf::circle_fit_start(tracks);
    std::string note;
    const cf::FootFitOptions options = options_for(p2, start.z_min, note);
    const cf::FootFitResult hm = cf::fit_hm(tracks, start, options);
    const cf::FootFitResult hmt = cf::fit_hmt(tracks, hm, start.z_min, options);
    std::printf("%8.0f %7d %10.4f %10.4f %8d %8d %10.4f%s\n", rate, hm.samples, hm.seconds, hmt.seconds, hm.iterations,
                hmt.iterations, cyclopt::bench::cpu_seconds() - cpu0, hm.converged && hmt.converged ? "" : " NOT CONVERGED");
  }
  std::printf("%s at end\n", cyclopt::bench::load_average().c_str());
  return 0;
}
