// Issue 20 acceptance 1 and 3: the seed's fits (section 4.2) on synthetic trials of every
// catalogue foot: three trials at 200 Hz with 0.5 mm marker noise. Per foot and fit: recovery
// of the lengths and gamma_F within 4 standard errors (the covariance sigma^2 (J^T J)^-1 of the
// fit, i.e. a tolerance derived from the noise), the RMS residual against its expectation at
// that noise, HMT never worse than HM, and the time per fit with the number of samples.
//
// Issue 56, `foot_fit_bench recordings TEST_WALKING.trc MOTION_CAPTURE_WALK.trc GRF_WALK.mot`:
// OpenSim's public walking recordings. Per foot: the stances found, the fit and its time, the
// spreads; the kinematic stance boundaries against the force plates'; acceptance 3, the change
// of every parameter over a grid of moved stance boundaries (+-40 ms in 10 ms steps, cold fits
// as a user moving the interval gets them) against the reported spreads; and the HM bias
// (item 4): HM against HMT and against HM without the contact's first 40 ms.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot_fit/ankle_track.hpp"
#include "cyclopt/foot_fit/fit_spread.hpp"
#include "cyclopt/foot_fit/gait_trial_file.hpp"
#include "cyclopt/foot_fit/marker_file.hpp"
#include "cyclopt/foot_fit/opensim_storage_file.hpp"
#include "cyclopt/foot_fit/rolling_foot_fit.hpp"
#include "cyclopt/foot_fit/seed_fitted_ranges.hpp"
#include "cyclopt/foot_fit/synthetic_trials.hpp"
#include "machine_info.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
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

// ---- issue 56: real recordings ----

struct Foot {
  std::string name;
  cf::GaitTrial trial;
};

// What cyclopt-foot fit uses on recordings: the statistical stop of arrow_least_squares.hpp.
cf::FootFitOptions recording_options() {
  cf::FootFitOptions o;
  o.solver.parameter_tolerance = 1e-2;
  return o;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Lengths in mm, angles in rad, k in rad: the printed scale of parameter i.
double shown(const cf::ParameterEstimate& e, double v) { return e.unit == "m" ? 1e3 * v : v; }

void print_stances(const Foot& f) {
  std::printf("%s: vertical axis %s, walking direction %.4f rad\n", f.name.c_str(), f.trial.ankle.vertical_rule.c_str(),
              f.trial.ankle.walking_direction);
  for (std::size_t k = 0; k < f.trial.stances.size(); ++k) {
    const cf::Stance& s = f.trial.stances[k];
    std::printf("  stance %zu %.3f-%.3f s, %d frames, %s: %s%s\n", k + 1, s.start, s.end, s.last - s.first + 1, s.rule.c_str(),
                s.complete() ? "fitted" : "REFUSED ", s.refusal.c_str());
  }
}

void print_fit_line(const cf::FootFitResult& f) {
  std::printf("  %-3s %-13s RMS %.3f mm:", std::string(foot::to_string(f.model)).c_str(), f.converged ? "converged" : "NOT CONVERGED",
              1e3 * f.rms);
  for (const cf::ParameterEstimate& e : f.estimates)
    if (!e.fixed) std::printf(" %s %.4g%s", e.name.c_str(), shown(e, e.value), e.at_bound ? " (bound)" : "");
  std::printf("\n");
}

// Acceptance 3 on one foot: cold fits with every stance boundary moved on a 5 ms grid - twice as
// fine as the spread's own 10 ms grid, so most of these fits are not among its refits - against
// the reported spreads. `inward_only` keeps the shifts a loaded plate admits (start later, end
// earlier); without it, plate stances are moved outwards too, which the spread does not claim.
void boundary_grid(const Foot& f, const cf::RollingFootFit& fit, bool inward_only) {
  std::vector<double> shifts;
  for (int i = -8; i <= 8; ++i) shifts.push_back(0.005 * i);
  std::vector<double> hm_dev(fit.hm.estimates.size(), 0.0), hmt_dev(fit.hmt.estimates.size(), 0.0);
  int fits = 0, unconverged = 0, failed = 0;
  for (double ds : shifts)
    for (double de : shifts) {
      if ((ds == 0.0 && de == 0.0) || (inward_only && (ds < 0.0 || de > 0.0))) continue;
      ++fits;
      try {
        const cf::RollingFootFit g = cf::fit_rolling_foot(cf::stance_tracks({f.trial}, ds, de), recording_options());
        unconverged += (g.hm.converged && g.hmt.converged) ? 0 : 1;
        for (std::size_t i = 0; i < hm_dev.size(); ++i)
          hm_dev[i] = std::max(hm_dev[i], std::abs(g.hm.parameters[i] - fit.hm.parameters[i]));
        for (std::size_t i = 0; i < hmt_dev.size(); ++i)
          hmt_dev[i] = std::max(hmt_dev[i], std::abs(g.hmt.parameters[i] - fit.hmt.parameters[i]));
      } catch (const std::exception& e) {
        ++failed;
      }
    }
  std::printf("  grid %s: %d cold fits (%d with a fit not converged, counted where it stopped; %d without a start)\n",
              inward_only ? "start 0..+40 ms x end -40..0 ms in 5 ms steps (inside the plate contact)"
                          : "start and end -40..+40 ms in 5 ms steps",
              fits, unconverged, failed);
  std::printf("  %-4s %-8s %10s %10s %10s %10s %9s %s\n", "fit", "param", "value", "grid dev", "bound spr", "stride spr", "dev/spr",
              "covered");
  for (const auto& [r, dev] : {std::pair{&fit.hm, &hm_dev}, std::pair{&fit.hmt, &hmt_dev}})
    for (std::size_t i = 0; i < dev->size(); ++i) {
      const cf::ParameterEstimate& e = r->estimates[i];
      if (e.fixed) continue;
      const double reported = std::max(e.boundary_spread, std::isnan(e.stride_spread) ? 0.0 : e.stride_spread);
      std::printf("  %-4s %-8s %10.4g %10.4g %10.4g %10.4g %9.2f %s\n", std::string(foot::to_string(r->model)).c_str(),
                  e.name.c_str(), shown(e, e.value), shown(e, (*dev)[i]), shown(e, e.boundary_spread), shown(e, e.stride_spread),
                  (*dev)[i] / reported, (*dev)[i] <= reported * (1.0 + 1e-9) ? "yes" : "NO");
    }
}

// HM bias (item 4): HM residual in the first 40 ms of each stance against the rest, and HM refitted
// without those 40 ms.
void hm_bias(const Foot& f, const cf::RollingFootFit& fit) {
  const std::vector<cf::AnkleTrack> tracks = cf::stance_tracks({f.trial});
  double early2 = 0.0, late2 = 0.0;
  int early = 0, late = 0;
  for (std::size_t k = 0; k < tracks.size(); ++k)
    for (int j = 0; j < tracks[k].samples(); ++j) {
      const double d2 = (fit.hm.model_ankle(static_cast<int>(k), j) - Eigen::Vector2d(tracks[k].x[j], tracks[k].z[j])).squaredNorm();
      if (tracks[k].time[j] < tracks[k].time.front() + 0.04) {
        early2 += d2;
        ++early;
      } else {
        late2 += d2;
        ++late;
      }
    }
  std::printf("  HM residual RMS: first 40 ms of the stances %.3f mm (%d samples), the rest %.3f mm (%d samples)\n",
              1e3 * std::sqrt(early2 / early), early, 1e3 * std::sqrt(late2 / late), late);
  const cf::RollingFootFit trimmed = cf::fit_rolling_foot(cf::stance_tracks({f.trial}, 0.04, 0.0), recording_options());
  std::printf("  without the first 40 ms:\n");
  print_fit_line(trimmed.hm);
  print_fit_line(trimmed.hmt);
  // Without the roll over the toes: each stance ends where the ankle, past its lowest point, has
  // risen 20 mm (heel-off and the start of the forefoot roll kept).
  std::vector<cf::AnkleTrack> no_toes = tracks;
  for (cf::AnkleTrack& t : no_toes) {
    const int low = static_cast<int>(std::min_element(t.z.begin(), t.z.end()) - t.z.begin());
    int end = low;
    while (end + 1 < t.samples() && t.z[end + 1] < t.z[low] + 0.02) ++end;
    t.time.resize(end + 1);
    t.x.resize(end + 1);
    t.z.resize(end + 1);
  }
  const cf::RollingFootFit toeless = cf::fit_rolling_foot(no_toes, recording_options());
  std::printf("  without the roll over the toes (ankle more than 20 mm above its lowest point after it):\n");
  print_fit_line(toeless.hm);
}

int recordings(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: foot_fit_bench recordings TEST_WALKING.trc MOTION_CAPTURE_WALK.trc GRF_WALK.mot\n");
    return 2;
  }
  std::printf("foot_fit_bench recordings on %s, %s at start\n", cyclopt::bench::machine_line().c_str(),
              cyclopt::bench::load_average().c_str());
  for (int a = 2; a < 5; ++a) {
    const std::string path = argv[a];
    if (path.size() > 4 && path.substr(path.size() - 4) == ".mot") {
      const cf::StorageTable t = cf::read_opensim_storage(path);
      std::printf("read %s: %d rows at %.0f Hz, %zu columns\n", path.c_str(), t.rows(), 1.0 / (t.time[1] - t.time[0]), t.names.size() + 1);
    } else {
      const cf::MarkerTrial t = cf::read_marker_file(path);
      std::printf("read %s: %d frames at %.0f Hz, %zu markers, unit %s\n", path.c_str(), t.samples(), 1.0 / (t.time[1] - t.time[0]),
                  t.marker_names.size(), t.units.c_str());
    }
  }
  std::vector<Foot> feet;
  for (const char* side : {"R", "L"}) {
    cf::GaitTrialOptions o;
    o.ankle.markers = {std::string(side) + "LMAL", std::string(side) + "MMAL"};
    feet.push_back({std::string("test_walking ") + (side[0] == 'R' ? "right" : "left") + " (malleoli, kinematics)",
                    cf::read_gait_trial(argv[2], o)});
  }
  for (const char* side : {"R", "L"}) {
    cf::GaitTrialOptions o;
    o.ankle.markers = {std::string(side) + ".Ankle"};
    o.forces_file = argv[4];
    feet.push_back({std::string("motion_capture_walk ") + (side[0] == 'R' ? "right" : "left") + " (ankle marker, force plates)",
                    cf::read_gait_trial(argv[3], o)});
  }

  std::printf("\nKinematic stance rule against the force plates (motion_capture_walk, %.1f m/s, flat-foot frame below %.2f m/s):\n",
              cf::StanceOptions{}.max_rolling_speed, cf::StanceOptions{}.still_speed);
  for (std::size_t f = 2; f < feet.size(); ++f) {
    const std::vector<cf::Stance> kin = cf::kinematic_stances(feet[f].trial.ankle);
    for (const cf::Stance& s : feet[f].trial.stances)
      for (const cf::Stance& k : kin)
        if (k.end > s.start && k.start < s.end)
          std::printf("  %s: plate %.3f-%.3f s, kinematics %.3f-%.3f s: start %+.0f ms, end %+.0f ms%s\n", feet[f].name.c_str(),
                      s.start, s.end, k.start, k.end, 1e3 * (k.start - s.start), 1e3 * (k.end - s.end),
                      k.complete() ? "" : " (kinematic stance refused)");
  }

  for (const Foot& f : feet) {
    std::printf("\n");
    print_stances(f);
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = cyclopt::bench::cpu_seconds();
    cf::RollingFootFit fit = cf::fit_rolling_foot(cf::stance_tracks({f.trial}), recording_options());
    const double fit_seconds = seconds_since(t0);
    const cf::FitSpread spread = cf::add_fit_spread(fit, {f.trial}, recording_options());
    std::printf("  time: fit %.3f s, spreads %.3f s (%zu refits), together %.3f s wall, %.3f s CPU; %s\n", fit_seconds, spread.seconds,
                spread.refits.size(), seconds_since(t0), cyclopt::bench::cpu_seconds() - cpu0, cyclopt::bench::load_average().c_str());
    print_fit_line(fit.hm);
    print_fit_line(fit.hmt);
    bool in_range = true;
    for (int i : {foot::hmt::h_F, foot::hmt::l_HA, foot::hmt::l_HM, foot::hmt::l_MT, foot::hmt::gamma_F}) {
      const cf::SeedRange r = cf::seed_fitted_range(foot::FootModel::hmt, i);
      in_range = in_range && fit.hmt.parameters[i] >= r.low && fit.hmt.parameters[i] <= r.high;
    }
    std::printf("  HMT in the seed's ranges (h_F 61-116, l_HA 7-154, l_HM 161-379, l_MT 0-126 mm, gamma_F 0.52-1.57 rad): %s\n",
                in_range ? "yes" : "NO");
    for (const cf::Refit& r : spread.refits)
      if (!r.note.empty()) std::printf("  refit %s: %s\n", r.what.c_str(), r.note.c_str());
    const bool contact = f.trial.complete_stances() > 0 && f.trial.stances[0].contact;
    boundary_grid(f, fit, contact);
    if (contact) boundary_grid(f, fit, false);
    hm_bias(f, fit);
    std::fflush(stdout);
  }
  std::printf("\n%s at end\n", cyclopt::bench::load_average().c_str());
  return 0;
}

}  // namespace

// Usage: foot_fit_bench [STRIDE]: every STRIDE-th catalogue foot (default 1: all 216);
// foot_fit_bench recordings ...: the real recordings (above).
int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "recordings") == 0) return recordings(argc, argv);
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
