// Issue 20 acceptance 1 and 3: the seed's fits (section 4.2) on synthetic trials of every
// catalogue foot: three trials at 200 Hz with 0.5 mm marker noise. Per foot and fit: recovery
// of the lengths and gamma_F within 4 standard errors (the covariance sigma^2 (J^T J)^-1 of the
// fit, i.e. a tolerance derived from the noise), the RMS residual against its expectation at
// that noise, HMT never worse than HM, and the time per fit with the number of samples.
//
// Issue 56, `foot_fit_bench recordings TEST_WALKING.trc MOTION_CAPTURE_WALK.trc GRF_WALK.mot`:
// OpenSim's public walking recordings. Per foot: the stances found, the fit and its time, the
// spreads; the kinematic stance boundaries against the force plates'; acceptance 3, the change
// of every parameter over grids of moved stance boundaries (+-40 ms in steps of 5 ms, one frame
// and 1 ms, cold fits as a user moving the interval gets them) against the reported boundary
// spreads; and the HM bias (item 4): HM against HMT and against HM without the contact's first
// 40 ms.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot_fit/ankle_track.hpp"
#include "cyclopt/foot_fit/boundary_grid.hpp"
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
#include <cstdio>
#include <exception>
#include <map>
#include <set>
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

// Acceptance 3 on one foot: cold fits with every stance boundary moved on grids of 5 ms, one
// frame and 1 ms up to +-40 ms, against the reported boundary spreads. A fit depends only on the
// frames it is given, so each distinct set of stance windows is fitted once (shared by the
// grids); a grid point whose windows are not among the spread's refits is counted (none, by
// construction: boundary_grid.hpp). `inward_only` keeps the shifts a loaded plate admits (start
// later, end earlier); without it, plate stances are moved outwards too, which the spread does
// not claim.
void boundary_check(const Foot& f, const cf::RollingFootFit& fit, bool inward_only) {
  struct Fit {
    bool started = false, converged = false;
    foot::FootParameters<double> hm, hmt;
  };
  std::map<cf::StanceWindows, Fit> fits;
  std::set<cf::StanceWindows> refitted{cf::stance_windows(cf::stance_tracks({f.trial}))};
  for (const cf::MovedBoundaries& m : cf::boundary_grid({f.trial}, cf::SpreadOptions{}.boundary_tolerance, 0))
    refitted.insert(cf::stance_windows(m.tracks));
  const double frame = f.trial.ankle.time[1] - f.trial.ankle.time[0];
  struct Grid {
    std::string name;
    double step;
    int points = 0, not_refitted = 0;
    std::set<cf::StanceWindows> windows{};
    std::vector<double> hm_dev{}, hmt_dev{};
  };
  char frame_name[32];
  std::snprintf(frame_name, sizeof frame_name, "%.0f ms", 1e3 * frame);
  std::vector<Grid> grids{{"5 ms", 0.005}, {frame_name, frame}, {"1 ms", 0.001}};
  for (Grid& g : grids) {
    g.hm_dev.assign(fit.hm.estimates.size(), 0.0);
    g.hmt_dev.assign(fit.hmt.estimates.size(), 0.0);
    const int n = static_cast<int>(std::floor(0.04 / g.step + 1e-9));
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j) {
        const double ds = g.step * i, de = g.step * j;
        if ((i == 0 && j == 0) || (inward_only && (ds < 0.0 || de > 0.0))) continue;
        ++g.points;
        std::vector<cf::AnkleTrack> tracks = cf::stance_tracks({f.trial}, ds, de);
        const cf::StanceWindows w = cf::stance_windows(tracks);
        g.not_refitted += refitted.count(w) ? 0 : 1;
        g.windows.insert(w);
        auto [it, fresh] = fits.try_emplace(w);
        if (fresh) try {
            const cf::RollingFootFit r = cf::fit_rolling_foot(tracks, recording_options());
            it->second = {true, r.hm.converged && r.hmt.converged, r.hm.parameters, r.hmt.parameters};
          } catch (const std::exception&) {  // no circle-fit start: left out, as the spread leaves it out
          }
        if (!it->second.started) continue;
        for (std::size_t p = 0; p < g.hm_dev.size(); ++p)
          g.hm_dev[p] = std::max(g.hm_dev[p], std::abs(it->second.hm[p] - fit.hm.parameters[p]));
        for (std::size_t p = 0; p < g.hmt_dev.size(); ++p)
          g.hmt_dev[p] = std::max(g.hmt_dev[p], std::abs(it->second.hmt[p] - fit.hmt.parameters[p]));
      }
  }
  int unconverged = 0, failed = 0;
  for (const auto& [w, r] : fits) {
    failed += r.started ? 0 : 1;
    unconverged += r.started && !r.converged ? 1 : 0;
  }
  std::printf("  boundary check, %s: %zu distinct stance windows over the grids, each a cold fit (%d with a fit not converged, "
              "counted where it stopped; %d without a start)\n",
              inward_only ? "start 0..+40 ms x end -40..0 ms (inside the plate contact)" : "start and end -40..+40 ms",
              fits.size(), unconverged, failed);
  for (const Grid& g : grids)
    std::printf("    %-5s grid: %5d shifts, %4zu windows, %d not among the spread's refits\n", g.name.c_str(), g.points,
                g.windows.size(), g.not_refitted);
  std::printf("  %-4s %-8s %10s %10s %10s %10s %10s %9s %9s %9s %s\n", "fit", "param", "value", "bound spr", "stride spr",
              "dev 5 ms", "dev 1 ms", "5 ms/spr", (grids[1].name + "/spr").c_str(), "1 ms/spr", "covered");
  for (const cf::FootFitResult* r : {&fit.hm, &fit.hmt})
    for (std::size_t i = 0; i < r->estimates.size(); ++i) {
      const cf::ParameterEstimate& e = r->estimates[i];
      if (e.fixed) continue;
      std::vector<double> dev;
      for (const Grid& g : grids) dev.push_back((r == &fit.hm ? g.hm_dev : g.hmt_dev)[i]);
      const bool covered = *std::max_element(dev.begin(), dev.end()) <= e.boundary_spread;
      std::printf("  %-4s %-8s %10.4g %10.4g %10.4g %10.4g %10.4g %9.2f %9.2f %9.2f %s\n", std::string(foot::to_string(r->model)).c_str(),
                  e.name.c_str(), shown(e, e.value), shown(e, e.boundary_spread), shown(e, e.stride_spread), shown(e, dev[0]),
                  shown(e, dev[2]), dev[0] / e.boundary_spread, dev[1] / e.boundary_spread, dev[2] / e.boundary_spread,
                  covered ? "yes" : "NO");
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
    std::printf("  time: fit %.3f s, spreads %.3f s (%zu refits, every frame), together %.3f s wall, %.3f s CPU; %s\n", fit_seconds,
                spread.seconds, spread.refits.size(), seconds_since(t0), cyclopt::bench::cpu_seconds() - cpu0,
                cyclopt::bench::load_average().c_str());
    {  // the coarser grid cyclopt-foot fit --boundary-steps 4 gives, for its time
      cf::RollingFootFit coarse = fit;
      cf::SpreadOptions o;
      o.boundary_steps = 4;
      const double cpu1 = cyclopt::bench::cpu_seconds();
      const cf::FitSpread s4 = cf::add_fit_spread(coarse, {f.trial}, recording_options(), o);
      std::printf("  time with boundary_steps 4 (10 ms grid): spreads %.3f s (%zu refits), %.3f s CPU\n", s4.seconds, s4.refits.size(),
                  cyclopt::bench::cpu_seconds() - cpu1);
    }
    print_fit_line(fit.hm);
    print_fit_line(fit.hmt);
    bool in_range = true;
    for (int i : {foot::hmt::h_F, foot::hmt::l_HA, foot::hmt::l_HM, foot::hmt::l_MT, foot::hmt::gamma_F}) {
      const cf::SeedRange r = cf::seed_fitted_range(foot::FootModel::hmt, i);
      in_range = in_range && fit.hmt.parameters[i] >= r.low && fit.hmt.parameters[i] <= r.high;
    }
    std::printf("  HMT in the seed's ranges (h_F 61-116, l_HA 7-154, l_HM 161-379, l_MT 0-126 mm, gamma_F 0.52-1.57 rad): %s\n",
                in_range ? "yes" : "NO");
    int unconverged = 0, unstarted = 0;
    for (const cf::Refit& r : spread.refits) {
      unstarted += r.started ? 0 : 1;
      unconverged += r.started && !(r.hm_converged && r.hmt_converged) ? 1 : 0;
    }
    std::printf("  refits: %d with a fit not converged (counted where it stopped), %d without a start (left out)\n", unconverged,
                unstarted);
    const bool contact = f.trial.complete_stances() > 0 && f.trial.stances[0].contact;
    boundary_check(f, fit, contact);
    if (contact) boundary_check(f, fit, false);
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
