#include "cyclopt/foot_fit/fit_spread.hpp"

#include "cyclopt/foot_fit/boundary_grid.hpp"
#include "cyclopt/foot_fit/seed_fitted_ranges.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <thread>

namespace cyclopt::foot_fit {
namespace {

std::string shift_text(double start, double end) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "start %+.0f ms, end %+.0f ms", start == 0.0 ? 0.0 : 1e3 * start, end == 0.0 ? 0.0 : 1e3 * end);
  return buf;
}

Refit refit(const std::vector<AnkleTrack>& tracks, const FootFitOptions& options, std::string what, bool stride) {
  Refit r{std::move(what), stride, false, false, false, {}, {}, {}};
  try {
    const RollingFootFit f = fit_rolling_foot(tracks, options);
    r.started = true;
    r.hm_converged = f.hm.converged;
    r.hmt_converged = f.hmt.converged;
    r.hm = f.hm.parameters;
    r.hmt = f.hmt.parameters;
    for (const FootFitResult* m : {&f.hm, &f.hmt})
      if (!m->converged)
        r.note += (r.note.empty() ? "" : "; ") + std::string(foot::to_string(m->model)) + " fit did not converge (" + m->message + ")";
  } catch (const std::invalid_argument& e) {  // the circle-fit start needs both sides of the lowest point
    r.note = std::string("cannot start: ") + e.what();
  }
  return r;
}

// Writes the spreads of one model's estimates from the refits' parameters `of`.
void write_spreads(FootFitResult& fit, const std::vector<Refit>& refits, foot::FootParameters<double> Refit::*of,
                   bool Refit::*converged, const SpreadOptions& o) {
  fit.spread_refits = fit.spread_unconverged = 0;
  for (const Refit& r : refits)
    if (r.started) {
      ++fit.spread_refits;
      fit.spread_unconverged += r.*converged ? 0 : 1;
    }
  fit.boundary_tolerance = o.boundary_tolerance;
  for (std::size_t i = 0; i < fit.estimates.size(); ++i) {
    ParameterEstimate& e = fit.estimates[i];
    if (e.fixed) continue;
    std::vector<double> strides;
    double boundary = std::numeric_limits<double>::quiet_NaN();
    for (const Refit& r : refits) {
      if (!r.started) continue;
      const double v = (r.*of)[static_cast<Eigen::Index>(i)];
      if (r.stride)
        strides.push_back(v);
      else
        boundary = std::isnan(boundary) ? std::abs(v - e.value) : std::max(boundary, std::abs(v - e.value));
    }
    if (strides.size() >= 2) {  // jackknife standard error
      const double k = double(strides.size());
      double mean = 0.0, sum2 = 0.0;
      for (double v : strides) mean += v / k;
      for (double v : strides) sum2 += (v - mean) * (v - mean);
      e.stride_spread = std::sqrt((k - 1.0) / k * sum2);
    }
    e.boundary_spread = boundary;
    const SeedRange range = seed_fitted_range(fit.model, static_cast<int>(i));
    std::vector<std::string> why;
    if (e.at_bound) why.push_back("on its bound");
    char buf[160];
    for (const auto& [name, spread] : {std::pair{"stride", e.stride_spread}, std::pair{"boundary", e.boundary_spread}})
      if (spread > o.flag_fraction * range.width()) {
        std::snprintf(buf, sizeof buf, "%s spread %.0f%% of the seed's range %.3g-%.3g %s", name, 100.0 * spread / range.width(),
                      range.low, range.high, e.unit.c_str());
        why.emplace_back(buf);
      }
    e.flag.clear();
    for (const std::string& w : why) e.flag += (e.flag.empty() ? "" : "; ") + w;
  }
}

}  // namespace

FitSpread add_fit_spread(RollingFootFit& fit, const std::vector<GaitTrial>& trials, const FootFitOptions& fit_options,
                         const SpreadOptions& o, const RefitProgress& on_refit) {
  if (!(o.boundary_tolerance >= 0.0 && o.boundary_tolerance <= 0.2))
    throw std::invalid_argument("boundary_tolerance: " + std::to_string(o.boundary_tolerance) + " s is not in [0, 0.2] s");
  if (!(o.flag_fraction > 0.0)) throw std::invalid_argument("flag_fraction: must be > 0");
  if (o.threads < 0) throw std::invalid_argument("threads: must be >= 0 (0: every core)");
  if (o.boundary_steps < 0 || o.boundary_steps > 20)
    throw std::invalid_argument("boundary_steps: " + std::to_string(o.boundary_steps) + " is not in [0, 20] (0: every frame)");
  const auto started = std::chrono::steady_clock::now();
  struct Job {
    std::vector<AnkleTrack> tracks;
    std::string what;
    bool stride;
  };
  std::vector<Job> jobs;
  const std::vector<AnkleTrack> all = stance_tracks(trials);
  if (all.size() >= 2)
    for (std::size_t k = 0; k < all.size(); ++k) {
      std::vector<AnkleTrack> rest = all;
      rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(k));
      jobs.push_back({rest, "without " + all[k].source, true});
    }
  // Boundary refits: every distinct set of stance windows over the grid (boundary_grid.hpp).
  for (MovedBoundaries& m : boundary_grid(trials, o.boundary_tolerance, o.boundary_steps))
    jobs.push_back({std::move(m.tracks), shift_text(m.start_shift, m.end_shift), false});
  // Independent solves: each thread takes the next job, so the result does not depend on the
  // number of threads.
  FitSpread spread;
  spread.refits.resize(jobs.size());
  std::atomic<std::size_t> next{0}, done{0};
  auto work = [&](bool reports) {
    for (std::size_t j = next++; j < jobs.size(); j = next++) {
      spread.refits[j] = refit(jobs[j].tracks, fit_options, jobs[j].what, jobs[j].stride);
      const std::size_t finished = ++done;
      if (reports && on_refit) on_refit(finished, jobs.size());
    }
  };
  const int threads = std::min<int>(o.threads > 0 ? o.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency())),
                                    static_cast<int>(jobs.size()));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, false);
  work(true);
  for (std::thread& t : pool) t.join();
  if (on_refit) on_refit(jobs.size(), jobs.size());
  write_spreads(fit.hm, spread.refits, &Refit::hm, &Refit::hm_converged, o);
  write_spreads(fit.hmt, spread.refits, &Refit::hmt, &Refit::hmt_converged, o);
  spread.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return spread;
}

}  // namespace cyclopt::foot_fit
