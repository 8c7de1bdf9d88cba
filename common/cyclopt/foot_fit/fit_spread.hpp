#pragma once
// How sure a foot fit is. The standard errors of rolling_foot_fit.hpp are conditional: they
// assume the model exact and the rolling phase known. On gait-lab recordings neither holds -
// moving a stance boundary by 40 ms moves a length by tens of millimetres, ten times the
// standard error - so two empirical spreads are reported beside them, from refits of the
// seed's three steps (section 4.2) on altered data:
//  - over the strides, with K >= 2 complete stances: the jackknife standard error of the K fits
//    that each leave one stance out, sqrt((K-1)/K sum (p_(k) - mean)^2);
//  - over the boundaries: the largest change of a parameter when the start and the end of every
//    stance move up to +-boundary_tolerance, each distinct set of stance windows refitted once
//    (boundary_grid.hpp). By default every shift that puts a boundary on a frame is tried, so
//    every window that any shift within the tolerance gives is refitted (21 x 21 - 1 = 440 refits
//    for one kinematic stance set at 250 Hz, 80 at 100 Hz): on real recordings the HMT fit hops
//    between local optima as a boundary moves, so the change is not monotone in the shift, and a
//    coarser grid misses changes between its points (coverage and time:
//    bench/results/foot_fit_real_data.txt). boundary_steps n >= 1 trades that for time: the grid
//    {0, +-boundary_tolerance/n, ..., +-boundary_tolerance} ((2n + 1)^2 - 1 refits).
//    A stance bounded by a loaded plate only shrinks (start later, end earlier; 5 x 5 - 1 = 24
//    refits at 100 Hz): the rolling phase lies within the contact the plate measured, but how
//    much of the contact's first and last tens of milliseconds (heel impact, toe flexion) is
//    rigid rolling is uncertain.
// A parameter is flagged when it sits on a bound, or when a spread exceeds flag_fraction of the
// range the seed's own fits of that parameter span (seed_fitted_ranges.hpp).

#include "cyclopt/foot_fit/rolling_foot_fit.hpp"
#include "cyclopt/foot_fit/stances.hpp"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace cyclopt::foot_fit {

struct SpreadOptions {
  // s: how far a stance boundary is uncertain. Kinematic heel strike and toe-off fall tens of
  // milliseconds from the force plates' (bench/results/foot_fit_real_data.txt); and where the
  // foot loads the plate, its first and last tens of milliseconds (heel impact, toe flexion) are
  // not rigid rolling.
  double boundary_tolerance = 0.04;
  int boundary_steps = 0;  // 0: every frame; n: grid points per side (4: shifts of 10 ms at 40 ms)
  double flag_fraction = 0.25;
  int threads = 0;  // refits run in parallel, 0: one thread per core; the results do not depend on it
};

// One refit: which data, and its HM and HMT parameters. A refit that stops at the iteration
// limit counts with the point it reached: on these data that is a solver creeping along a flat
// valley of the cost, whose length is what the spread is to show (it is counted apart).
struct Refit {
  std::string what;  // "without FILE stance 2 (...)", "start -40 ms, end +40 ms"
  bool stride = false;
  bool started = false;  // false: the circle-fit start failed, the refit is left out
  bool hm_converged = false, hmt_converged = false;
  foot::FootParameters<double> hm, hmt;
  std::string note;  // why it did not start or converge; empty when it did
};

struct FitSpread {
  std::vector<Refit> refits;
  double seconds = 0.0;
};

// How far the refits are: `done` of `total`. Called on the calling thread only (which refits
// too): after each of its own refits and once at the end with done == total.
using RefitProgress = std::function<void(std::size_t done, std::size_t total)>;

// Refits the trials' complete stances (stance_tracks) as `options` says and writes the spreads
// and flags into the estimates of `fit` (ParameterEstimate::stride_spread, boundary_spread,
// flag) and the counts into FootFitResult::spread_refits, spread_unconverged.
FitSpread add_fit_spread(RollingFootFit& fit, const std::vector<GaitTrial>& trials, const FootFitOptions& fit_options = {},
                         const SpreadOptions& options = {}, const RefitProgress& on_refit = {});

}  // namespace cyclopt::foot_fit
