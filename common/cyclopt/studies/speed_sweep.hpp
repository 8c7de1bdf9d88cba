#pragma once
// The automatic study workflow of seed 001 chapter 9 (Fig. 9.7) over the mean speed:
//   1. multistart at a few seed speeds (0.3, 1.3, 2.3 m/s) from the automatic starting gait;
//   2. the best optimum of each (unless it lies on a curve already found) is continued with the
//      QPSQP method in both directions over the whole speed grid;
//   3. every curve jumped to is continued back, against the direction it was found in, so its
//      extent is known (the seed chose the existence ranges by hand);
//   4. per grid speed, the best converged point of all curves is selected (by hand in the seed).
#include "cyclopt/continuation/continuation_solver.hpp"
#include "cyclopt/walker/gait_problem.hpp"
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cyclopt::studies {

using continuation::ContinuationOptions;
using continuation::ContinuationResult;
using continuation::CurvePoint;
using continuation::PointCallback;

struct SpeedSweepOptions {
  std::vector<double> speeds;                       // the grid, strictly ascending, >= 2 values
  std::vector<double> seed_speeds{0.3, 1.3, 2.3};   // multistart at the nearest grid values
  int starts = 20;                                  // multistart runs per seed speed (seed: 20)
  std::uint64_t seed = 1;                           // base seed of the random perturbations
  double scale = 0.05;                              // rad, of the perturbations
  int max_curves = 12;                              // curves continued at most (each jump opens one)
  // A seed optimum lies on a known curve if a converged point there has |f - f_c| <=
  // same_objective * max(1, |f|) and |x - x_c|_inf <= same_x.
  double same_objective = 1e-6;
  double same_x = 1e-3;
  ContinuationOptions continuation;                 // for the multistart solves too (corrector)
  // MaxIter of the corrector at each continuation point (the multistart solves keep
  // continuation.corrector.max_iterations): a corrector that has not converged by then counts as
  // failed and the trust region shrinks, instead of spending MaxIter = 2000 iterations per failing
  // try (HMT P2 downwards near 0.46 m/s: ~16000 corrector iterations per run). >= 1.
  int corrector_max_iterations = 300;
};

struct BestPoint {
  double speed = 0.0;
  bool found = false;
  CurvePoint point;    // when found
  std::string reason;  // when not
};

struct SpeedSweepResult {
  std::vector<ContinuationResult> runs;  // in the order run
  std::vector<BestPoint> best;           // one per grid speed
  int curves = 0;                        // curve ids used: 0 .. curves - 1
  int multistart_solves = 0;
  double multistart_seconds = 0.0;
  double seconds = 0.0;
};

// on_point gets every new point (never the repeated first point of a run that starts on a point
// already reported); returning false stops the sweep (the result then holds what was done).
SpeedSweepResult speed_sweep(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                             const SpeedSweepOptions& options, const PointCallback& on_point = {});

}  // namespace cyclopt::studies
