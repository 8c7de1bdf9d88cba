#include "foot_fit_commands.hpp"

#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/io/foot_fit_json.hpp"
#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/foot_fit/ankle_track.hpp"
#include "cyclopt/foot_fit/fit_spread.hpp"
#include "cyclopt/foot_fit/gait_trial_file.hpp"
#include "cyclopt/foot_fit/marker_csv_file.hpp"
#include "cyclopt/foot_fit/rolling_foot_fit.hpp"
#include "cyclopt/foot_fit/synthetic_trials.hpp"
#include "cyclopt/foot_fit/trc_file.hpp"
#include "cyclopt/plot/foot_fit_figures.hpp"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace cyclopt::client {
namespace {

namespace ff = cyclopt::foot_fit;

constexpr const char* kFitUsage = R"(usage: cyclopt-foot fit [options] TRIAL.trc|TRIAL.csv [--forces GRF.mot] ...

Fits the HM and HMT feet to one foot's ankle trajectory over every complete
stance of the trials (seed 001, section 4.2): two circle fits for the start (eq.
4.9-4.12), the HM fit (4.13-4.17), the HMT fit started from it (4.18-4.22), then
refits that say how sure each parameter is. Units are SI on output (m, rad).

Reading: the ankle is the mean of two malleolus markers or one marker (eq. 4.1);
missing samples (empty, NaN, or a marker at exactly 0,0,0) of other markers are
ignored, gaps in the ankle markers up to --max-gap are interpolated. Stances
come from, first that applies: --interval; a ground-reaction file (--forces,
plates assigned to this foot by centre of pressure); a CSV force column (Fz);
else the ankle's kinematics. A stance that the recording or a long gap cuts is
refused with the reason and not fitted.

  --marker NAME        ankle marker; give it twice for the two malleoli whose
                       mean is the ankle (eq. 4.1); default LMAL and MMAL
  --forces FILE        OpenSim ground reactions (.mot, .sto) of the trial named
                       before it
  --force-column NAME  the vertical force column (in --forces, or the CSV's;
                       default: every plate of --forces by centre of pressure,
                       or the CSV's Fz)
  --force-threshold N  |force| above which a plate is loaded (default 20 N)
  --units mm|cm|m      unit of CSV files without a '# units:' line (.trc files
                       state theirs)
  --vertical-axis A    x, y or z: the file axis that points up (default:
                       detected from the data)
  --ground Z           ground level along the vertical axis, m (default 0)
  --direction RAD      walking direction in the horizontal plane (default: from
                       the data, 4.2-4.3)
  --max-gap S          longest gap of the ankle markers that is interpolated
                       (default 0.05 s)
  --interval T0:T1     one stance as a time interval (s), taken as given
  --max-rolling-speed V
                       kinematic rule: a stance is a run slower than V m/s
                       holding a flat-foot frame (default 2)
  --boundary-tolerance S
                       how far stance boundaries are moved for the boundary
                       spread (default 0.04 s); 0 skips it
  --boundary-steps N   0 (default): every shift that puts a stance boundary on
                       a frame, so the spread covers every window a shift
                       within the tolerance gives (kinematic stances at 250 Hz:
                       440 refits, seconds per foot; force-plate stances only
                       shrink: 24 at 100 Hz); N in 1-20: a coarser, faster grid
                       of N points per side ((2N+1)^2 - 1 refits; 4: 10 ms, 80)
  --no-spread          no refits: conditional standard errors only
  --parameter-tolerance F
                       stop a fit when its Gauss-Newton step moves no parameter
                       by F of its standard error (default 0.01; 0: only the
                       decrease tests, as a foot_fit job)
  --model HM|HMT|both  which fits to report (default both; HMT always starts
                       from HM)
  --no-toe-bound       drop the seed's l_MT <= z_min (4.18b)
  --save-foot FILE     write the fitted foot (HMT unless --model HM) as a foot
                       spec JSON, usable as `cyclopt-foot --foot FILE` and as
                       the "foot" of a walker job
  --plot-dir DIR       write fit_stances_K (ankle height over time with the
                       stances, per trial), fit_{hm,hmt}_ankle (Fig. 4.3a/4.4a)
                       and fit_{hm,hmt}_outline (Fig. 4.3b/4.4b) as .png and
                       .svg
  --json               print the full report as JSON (the HM and HMT records a
                       foot_fit job stores)
  --job-spec FILE      write a foot_fit job spec of the server
                       (docs/foot-fitting.md) with the stances' ankle tracks
                       inline instead of fitting: `cyclopt submit --spec FILE`
Exit codes: 0 fitted and converged, 1 a fit did not converge, 2 bad usage,
malformed file or no complete stance.
)";

constexpr const char* kSynthUsage = R"(usage: cyclopt-foot synth [--preset NAME | --foot FILE.json] --out DIR [options]

Writes synthetic marker trials of a known foot rolling on flat ground (ground
truth for `cyclopt-foot fit`): markers LMAL and MMAL either side of the ankle, a
force column Fz (CSV).

  --trials K          number of trials (default 3); trial k is offset by 0.11 m
                      (k-1), rolls 7% slower per trial and walks 0.02 rad more
                      to the left
  --rate HZ           sampling rate (default 200)
  --noise M           standard deviation of each marker coordinate, m (default
                      0.0005)
  --offset M          x_off of the first trial, m (default 0.4)
  --direction RAD     walking direction of the first trial (default 0)
  --theta T:TH,...    foot-angle history theta_F(t), piecewise linear knots
                      (s:rad); default -0.35 rad at heel strike, flat at 0.12 s,
                      toe-off at 0.62 s
  --swing S           seconds of swing before heel strike and after toe-off
                      (default 0.1: a stance that starts or ends with the
                      recording is refused by the fit)
  --format trc|csv|both  (default both)
  --units mm|cm|m     (default mm)
  --seed N            noise seed (default 1)
Exit codes: 0 written, 2 bad usage or foot.
)";

struct Args {
  int argc;
  char** argv;
  int i = 2;
  bool more() const { return i < argc; }
  std::string take() { return argv[i++]; }
  std::string value(const std::string& flag) {
    if (i >= argc) throw std::invalid_argument(flag + " needs a value");
    return argv[i++];
  }
};

double number(const std::string& flag, const std::string& text) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(v)) throw std::invalid_argument(flag + ": '" + text + "' is not a number");
  return v;
}

void print_fit(const ff::FootFitResult& f) {
  std::printf("%s fit (%s): %s after %d iterations, %.3f s, %d samples, %d unknowns\n", std::string(foot::to_string(f.model)).c_str(),
              f.model == foot::FootModel::hm ? "eq. 4.16" : "eq. 4.21", f.converged ? "converged" : "NOT CONVERGED",
              f.iterations, f.seconds, f.samples, f.unknowns);
  if (!f.converged) std::printf("  solver: %s\n", f.message.c_str());
  std::printf("  %-8s %12s %11s %11s %11s %11s %11s  %s\n", "param", "value", "std. error", "stride spr", "bound. spr",
              "lower", "upper", "unit");
  for (const ff::ParameterEstimate& e : f.estimates)
    std::printf("  %-8s %12.6g %11.3g %11.3g %11.3g %11.4g %11.4g  %s%s\n", e.name.c_str(), e.value, e.standard_error,
                e.stride_spread, e.boundary_spread, e.lower, e.upper, e.unit.c_str(),
                e.fixed ? " (fixed)" : e.flag.empty() ? "" : "  FLAGGED");
  for (const ff::ParameterEstimate& e : f.estimates)
    if (!e.flag.empty()) std::printf("    ! %s: %s\n", e.name.c_str(), e.flag.c_str());
  if (f.spread_refits > 0)
    std::printf("  spreads from %d refits (stride: jackknife over left-out stances; boundary: largest change with the "
                "stance boundaries moved by +-%.0f ms); %d stopped unconverged and count where they stopped\n",
                f.spread_refits, 1e3 * f.boundary_tolerance, f.spread_unconverged);
  std::printf("  residual: RMS %.4f mm, max %.4f mm, noise estimate %.4f mm per coordinate\n", 1e3 * f.rms,
              1e3 * f.max_residual, 1e3 * f.noise_estimate);
  for (std::size_t k = 0; k < f.trials.size(); ++k)
    std::printf("    %-44s %5d samples  RMS %.4f mm  max %.4f mm  x_off %.5f m\n", f.trials[k].source.c_str(),
                f.trials[k].samples, 1e3 * f.trials[k].rms, 1e3 * f.trials[k].max, f.x_off[k]);
  std::printf("  convexity (eq. %s): %s\n", f.model == foot::FootModel::hm ? "3.21" : "3.24 + toe margin",
              f.convexity.convex ? "convex" : "NOT CONVEX");
  for (std::size_t r = 0; r < f.convexity.names.size(); ++r)
    if (f.convexity.values[r] < 0.0 || (r + 1 == f.convexity.names.size() && f.model == foot::FootModel::hmt))
      std::printf("    %-44s %12.4g\n", f.convexity.names[r].c_str(), f.convexity.values[r]);
}

void print_trial(const ff::GaitTrial& t) {
  const ff::AnkleSeries& a = t.ankle;
  std::printf("trial %s: ankle %s, vertical axis %s, walking direction %.4f rad%s\n", a.source.c_str(),
              a.markers.size() == 1 ? a.markers[0].c_str() : (a.markers[0] + " + " + a.markers[1]).c_str(),
              a.vertical_rule.c_str(), a.walking_direction, a.direction_estimated ? " (from the data)" : " (given)");
  int filled = 0;
  for (const ff::AnkleGap& g : a.gaps) filled += g.filled ? 1 : 0;
  if (filled > 0) std::printf("  %d gap(s) of the ankle markers up to %.0f ms interpolated\n", filled, 1e3 * a.max_gap);
  for (const std::string& n : a.notes) std::printf("  note: %s\n", n.c_str());
  for (std::size_t k = 0; k < t.stances.size(); ++k) {
    const ff::Stance& s = t.stances[k];
    std::printf("  stance %zu: %.3f-%.3f s, %d frames, %s: %s%s\n", k + 1, s.start, s.end, s.last - s.first + 1, s.rule.c_str(),
                s.complete() ? "fitted" : "REFUSED, ", s.refusal.c_str());
  }
}

nlohmann::json trial_json(const ff::GaitTrial& t) {
  nlohmann::json stances = nlohmann::json::array();
  for (const ff::Stance& s : t.stances)
    stances.push_back({{"start", s.start}, {"end", s.end}, {"frames", s.last - s.first + 1}, {"rule", s.rule},
                       {"fitted", s.complete()}, {"refusal", s.refusal}});
  return {{"source", t.ankle.source}, {"vertical_axis", std::string(1, "xyz"[t.ankle.vertical_axis])},
          {"vertical_rule", t.ankle.vertical_rule}, {"walking_direction", t.ankle.walking_direction},
          {"direction_estimated", t.ankle.direction_estimated}, {"notes", t.ankle.notes}, {"stances", stances}};
}

// The refits that did not start or converge, one line per reason with how many and a few of them
// (every frame's window makes hundreds of refits; --json lists each).
void print_refit_notes(const ff::FitSpread& refits) {
  std::vector<std::pair<std::string, std::vector<std::string>>> by_reason;
  for (const ff::Refit& r : refits.refits) {
    if (r.note.empty()) continue;
    const std::string reason = r.note + (r.started ? " (counted where it stopped)" : " (left out)");
    auto it = std::find_if(by_reason.begin(), by_reason.end(), [&](const auto& g) { return g.first == reason; });
    if (it == by_reason.end()) it = by_reason.insert(by_reason.end(), {reason, {}});
    it->second.push_back(r.what);
  }
  constexpr std::size_t kShown = 3;
  for (const auto& [reason, whats] : by_reason) {
    std::string shown;
    for (std::size_t k = 0; k < std::min(whats.size(), kShown); ++k) shown += (k ? "; " : "") + whats[k];
    std::printf("refits %zu of %zu: %s - %s%s\n", whats.size(), refits.refits.size(), reason.c_str(), shown.c_str(),
                whats.size() > kShown ? "; ..." : "");
  }
}

// On a terminal, the refits' count on one line of stderr while they run (seconds per foot at
// 250 Hz), cleared when they end; elsewhere nothing, so logs and pipes stay as they were.
ff::RefitProgress spread_progress() {
  if (!isatty(fileno(stderr))) return {};
  using Clock = std::chrono::steady_clock;
  return [started = Clock::now(), shown = Clock::time_point{}, showing = false](std::size_t done, std::size_t total) mutable {
    const Clock::time_point now = Clock::now();
    if (done == total) {
      if (showing) std::fprintf(stderr, "\r%48s\r", "");
      showing = false;
    } else if (now - shown >= std::chrono::milliseconds(250)) {
      shown = now;
      showing = true;
      std::fprintf(stderr, "\rrefits for the spreads: %zu of %zu, %.0f s ", done, total,
                   std::chrono::duration<double>(now - started).count());
    }
  };
}

}  // namespace

int run_fit_command(int argc, char** argv) {
  Args a{argc, argv};
  ff::GaitTrialOptions trial_options;
  std::vector<std::string> markers, files, forces;  // forces[k]: of files[k], or empty
  std::string model = "both", save, plot_dir, job_spec;
  bool json = false, toe_bound = true, spread = true;
  double parameter_tolerance = 1e-2;  // arrow_least_squares.hpp: real recordings creep near sharp transitions
  ff::SpreadOptions spread_options;
  try {
    while (a.more()) {
      const std::string flag = a.take();
      if (flag == "--help" || flag == "-h") {
        std::fputs(kFitUsage, stdout);
        return 0;
      } else if (flag == "--marker") {
        markers.push_back(a.value(flag));
      } else if (flag == "--forces") {
        if (files.empty()) throw std::invalid_argument("--forces: name the trial it belongs to before it");
        if (!forces.back().empty()) throw std::invalid_argument("--forces: " + files.back() + " has two force files");
        forces.back() = a.value(flag);
      } else if (flag == "--units") {
        trial_options.units = a.value(flag);
        ff::metres_per_unit(*trial_options.units);
      } else if (flag == "--vertical-axis") {
        const std::string v = a.value(flag);
        if (v != "x" && v != "y" && v != "z") throw std::invalid_argument("--vertical-axis: '" + v + "' is not x, y or z");
        trial_options.ankle.vertical_axis = v[0] - 'x';
      } else if (flag == "--ground") {
        trial_options.ankle.ground_height = number(flag, a.value(flag));
      } else if (flag == "--direction") {
        trial_options.ankle.walking_direction = number(flag, a.value(flag));
      } else if (flag == "--max-gap") {
        trial_options.ankle.max_gap = number(flag, a.value(flag));
        if (!(trial_options.ankle.max_gap >= 0 && trial_options.ankle.max_gap <= 1))
          throw std::invalid_argument("--max-gap: must be in [0, 1] s");
      } else if (flag == "--interval") {
        const std::string v = a.value(flag);
        const std::size_t colon = v.find(':');
        if (colon == std::string::npos) throw std::invalid_argument("--interval: expected T0:T1 in s, got '" + v + "'");
        trial_options.interval = {{number(flag, v.substr(0, colon)), number(flag, v.substr(colon + 1))}};
      } else if (flag == "--force-column") {
        trial_options.force_column = a.value(flag);
      } else if (flag == "--force-threshold") {
        trial_options.stance.force_threshold = number(flag, a.value(flag));
        if (!(trial_options.stance.force_threshold >= 0)) throw std::invalid_argument("--force-threshold: must be >= 0 N");
      } else if (flag == "--max-rolling-speed") {
        trial_options.stance.max_rolling_speed = number(flag, a.value(flag));
        if (!(trial_options.stance.max_rolling_speed > 0)) throw std::invalid_argument("--max-rolling-speed: must be > 0 m/s");
      } else if (flag == "--boundary-tolerance") {
        spread_options.boundary_tolerance = number(flag, a.value(flag));
        if (!(spread_options.boundary_tolerance >= 0 && spread_options.boundary_tolerance <= 0.2))
          throw std::invalid_argument("--boundary-tolerance: must be in [0, 0.2] s");
      } else if (flag == "--boundary-steps") {
        const double n = number(flag, a.value(flag));
        if (!(n >= 0 && n <= 20 && n == std::floor(n)))
          throw std::invalid_argument("--boundary-steps: must be an integer in [0, 20] (0: every frame)");
        spread_options.boundary_steps = static_cast<int>(n);
      } else if (flag == "--parameter-tolerance") {
        parameter_tolerance = number(flag, a.value(flag));
        if (!(parameter_tolerance >= 0 && parameter_tolerance <= 1))
          throw std::invalid_argument("--parameter-tolerance: must be in [0, 1]");
      } else if (flag == "--no-spread") {
        spread = false;
      } else if (flag == "--model") {
        model = a.value(flag);
        if (model != "HM" && model != "HMT" && model != "both") throw std::invalid_argument("--model: '" + model + "' is not HM, HMT or both");
      } else if (flag == "--no-toe-bound") {
        toe_bound = false;
      } else if (flag == "--save-foot") {
        save = a.value(flag);
      } else if (flag == "--plot-dir") {
        plot_dir = a.value(flag);
      } else if (flag == "--json") {
        json = true;
      } else if (flag == "--job-spec") {
        job_spec = a.value(flag);
      } else if (!flag.empty() && flag[0] == '-') {
        throw std::invalid_argument("unknown option '" + flag + "'");
      } else {
        files.push_back(flag);
        forces.emplace_back();
      }
    }
    if (files.empty()) throw std::invalid_argument("no trial files given");
    if (!markers.empty()) trial_options.ankle.markers = markers;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cyclopt-foot fit: %s\n%s", e.what(), kFitUsage);
    return 2;
  }
  try {
    std::vector<ff::GaitTrial> trials;
    for (std::size_t k = 0; k < files.size(); ++k) {
      ff::GaitTrialOptions o = trial_options;
      o.forces_file = forces[k];
      trials.push_back(ff::read_gait_trial(files[k], o));
    }
    const std::vector<ff::AnkleTrack> tracks = ff::stance_tracks(trials);
    if (tracks.empty()) {
      std::string why;
      for (const ff::GaitTrial& t : trials) {
        why += "\n  " + t.ankle.source + ": " + std::to_string(t.stances.size()) + " stance(s) found";
        for (const ff::Stance& s : t.stances) why += "\n    " + s.rule + ", refused: " + s.refusal;
      }
      throw std::runtime_error("no complete stance to fit:" + why);
    }
    if (!job_spec.empty()) {
      std::ofstream out(job_spec);
      if (!out) throw std::runtime_error(job_spec + ": cannot write the file");
      out << io::foot_fit_job_spec(tracks, toe_bound).dump() << "\n";
      std::fprintf(stderr, "cyclopt-foot fit: wrote the foot_fit job spec %s\n", job_spec.c_str());
      return 0;
    }
    ff::FootFitOptions options;
    options.toe_bound = toe_bound;
    options.solver.parameter_tolerance = parameter_tolerance;
    ff::RollingFootFit fit = ff::fit_rolling_foot(tracks, options);
    ff::FitSpread refits;
    if (spread) refits = ff::add_fit_spread(fit, trials, options, spread_options, spread_progress());
    const ff::CircleFitStart& start = fit.start;
    std::vector<const ff::FootFitResult*> shown;
    if (model != "HMT") shown.push_back(&fit.hm);
    if (model != "HM") shown.push_back(&fit.hmt);
    if (json) {
      nlohmann::json out;
      out["trials"] = nlohmann::json::array();
      for (const ff::GaitTrial& t : trials) out["trials"].push_back(trial_json(t));
      out["start"] = {{"x_neg", start.heel.centre}, {"R_neg", start.heel.radius}, {"x_pos", start.forefoot.centre},
                      {"R_pos", start.forefoot.radius}, {"z_min", start.z_min}, {"h_F", start.hm[foot::hm::h_F]},
                      {"l_HA", start.hm[foot::hm::l_HA]}, {"l_HM", start.hm[foot::hm::l_HM]}};
      nlohmann::json notes = nlohmann::json::array();
      for (const ff::Refit& r : refits.refits)
        if (!r.note.empty()) notes.push_back({{"refit", r.what}, {"counted", r.started}, {"note", r.note}});
      out["spread"] = {{"seconds", refits.seconds}, {"refit_notes", notes}};
      for (const ff::FootFitResult* f : shown) out[f->model == foot::FootModel::hm ? "hm" : "hmt"] = io::foot_fit_record(*f);
      std::cout << out.dump(2) << "\n";
    } else {
      for (const ff::GaitTrial& t : trials) print_trial(t);
      std::printf("start (eq. 4.9-4.12): z_min %.5f m, heel circle x_neg %.5f m R %.5f m (%d points), forefoot circle "
                  "x_pos %.5f m R %.5f m (%d points)\n",
                  start.z_min, start.heel.centre, start.heel.radius, start.heel.samples, start.forefoot.centre,
                  start.forefoot.radius, start.forefoot.samples);
      for (const ff::FootFitResult* f : shown) print_fit(*f);
      print_refit_notes(refits);
      if (spread) std::printf("refits for the spreads: %.3f s\n", refits.seconds);
      if (model == "both")
        std::printf("HMT vs HM: RMS %.4f mm vs %.4f mm (%s)\n", 1e3 * fit.hmt.rms, 1e3 * fit.hm.rms,
                    fit.hmt.rms <= fit.hm.rms ? "HMT not worse" : "HMT WORSE than HM");
    }
    if (!save.empty()) {
      const ff::FootFitResult& f = model == "HM" ? fit.hm : fit.hmt;
      const foot::FootSpec spec = f.spec("fitted " + std::string(foot::to_string(f.model)) + " (" + files.front() + ")");
      foot::validate(spec);
      std::ofstream out(save);
      if (!out) throw std::runtime_error(save + ": cannot write the file");
      out << io::to_json(spec).dump(2) << "\n";
      std::fprintf(stderr, "cyclopt-foot fit: wrote %s\n", save.c_str());
    }
    if (!plot_dir.empty()) {
      std::vector<plot::Figure> figures = plot::stance_figures(trials);
      for (const ff::FootFitResult* f : shown) {
        if (!f->converged) {  // a fit that did not converge is not drawn as if it had
          std::fprintf(stderr, "cyclopt-foot fit: not drawn: %s fit did not converge (%s)\n",
                       std::string(foot::to_string(f->model)).c_str(), f->message.c_str());
          continue;
        }
        for (plot::Figure& figure : plot::fit_figures(tracks, *f)) figures.push_back(std::move(figure));
      }
      for (const plot::Figure& figure : figures) plot::write_figure(figure, plot_dir);
      std::fprintf(stderr, "cyclopt-foot fit: wrote the figures into %s\n", plot_dir.c_str());
    }
    for (const ff::FootFitResult* f : shown)
      if (!f->converged) return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cyclopt-foot fit: %s\n", e.what());
    return 2;
  }
  return 0;
}

int run_synth_command(int argc, char** argv) {
  Args a{argc, argv};
  std::string preset = "P2-shoes-left-HMT", file, out_dir, format = "both", units = "mm";
  int trials = 3;
  ff::SyntheticTrialOptions base;
  base.noise = 0.0005;
  base.offset = 0.4;
  base.swing_time = 0.1;
  try {
    while (a.more()) {
      const std::string flag = a.take();
      if (flag == "--help" || flag == "-h") {
        std::fputs(kSynthUsage, stdout);
        return 0;
      } else if (flag == "--preset") {
        preset = a.value(flag);
      } else if (flag == "--foot") {
        file = a.value(flag);
      } else if (flag == "--out") {
        out_dir = a.value(flag);
      } else if (flag == "--trials") {
        const double k = number(flag, a.value(flag));
        if (k < 1 || k > 100 || k != std::floor(k)) throw std::invalid_argument("--trials: must be an integer in [1, 100]");
        trials = static_cast<int>(k);
      } else if (flag == "--rate") {
        base.rate = number(flag, a.value(flag));
      } else if (flag == "--noise") {
        base.noise = number(flag, a.value(flag));
      } else if (flag == "--offset") {
        base.offset = number(flag, a.value(flag));
      } else if (flag == "--direction") {
        base.walking_direction = number(flag, a.value(flag));
      } else if (flag == "--swing") {
        base.swing_time = number(flag, a.value(flag));
      } else if (flag == "--seed") {
        base.seed = static_cast<std::uint64_t>(number(flag, a.value(flag)));
      } else if (flag == "--theta") {
        const std::string v = a.value(flag);
        std::size_t start = 0;
        while (start <= v.size()) {
          const std::size_t comma = std::min(v.find(',', start), v.size());
          const std::string knot = v.substr(start, comma - start);
          const std::size_t colon = knot.find(':');
          if (colon == std::string::npos) throw std::invalid_argument("--theta: knot '" + knot + "' is not T:THETA");
          base.foot_angle.push_back({number(flag, knot.substr(0, colon)), number(flag, knot.substr(colon + 1))});
          start = comma + 1;
        }
      } else if (flag == "--format") {
        format = a.value(flag);
        if (format != "trc" && format != "csv" && format != "both") throw std::invalid_argument("--format: trc, csv or both");
      } else if (flag == "--units") {
        units = a.value(flag);
        ff::metres_per_unit(units);
      } else {
        throw std::invalid_argument("unknown option '" + flag + "'");
      }
    }
    if (out_dir.empty()) throw std::invalid_argument("--out DIR is required");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cyclopt-foot synth: %s\n%s", e.what(), kSynthUsage);
    return 2;
  }
  try {
    foot::FootSpec spec;
    if (!file.empty()) {
      std::ifstream in(file);
      if (!in) throw std::runtime_error("cannot read " + file);
      spec = io::foot_spec_from_json(nlohmann::json::parse(in));
    } else {
      spec = foot::foot_preset(preset).spec;
    }
    std::filesystem::create_directories(out_dir);
    const std::vector<ff::FootAngleKnot> history = base.foot_angle.empty() ? ff::default_foot_angle_history(spec) : base.foot_angle;
    for (int k = 0; k < trials; ++k) {
      ff::SyntheticTrialOptions o = base;
      o.offset = base.offset + 0.11 * k;
      o.walking_direction = base.walking_direction + 0.02 * k;
      o.seed = base.seed + static_cast<std::uint64_t>(k);
      o.foot_angle = history;
      for (ff::FootAngleKnot& knot : o.foot_angle) knot.t *= 1.0 + 0.07 * k;
      o.source = "trial" + std::to_string(k + 1);
      const ff::MarkerTrial t = ff::synthetic_trial(spec, o);
      const std::string stem = out_dir + "/" + o.source;
      if (format != "csv") ff::write_trc(t, stem + ".trc", units);
      if (format != "trc") ff::write_marker_csv(t, stem + ".csv", units);
      std::printf("%s: %d samples at %.1f Hz, x_off %.4f m, direction %.4f rad, noise %.2g m\n", stem.c_str(), t.samples(),
                  o.rate, o.offset, o.walking_direction, o.noise);
    }
    std::printf("generating foot: %s\n", io::to_json(spec).dump().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cyclopt-foot synth: %s\n", e.what());
    return 2;
  }
  return 0;
}

}  // namespace cyclopt::client
