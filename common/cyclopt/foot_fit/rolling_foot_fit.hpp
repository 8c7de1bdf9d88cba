#pragma once
// Steps 2 and 3 of seed 001 section 4.2: the HM fit (eq. 4.13-4.17) and the HMT fit started
// from it (eq. 4.18-4.22). Unknowns are the shape parameters, every foot angle theta_F,k,j and
// the offsets x_off,k; the residual of sample j of trial k is the model ankle
// [x_off,k + F(p, theta) - F(p, 0), F'(p, theta)] (eq. 4.15 / 4.20) minus the measured one.

#include "cyclopt/foot/foot_spec.hpp"
#include "cyclopt/foot_fit/ankle_track.hpp"
#include "cyclopt/foot_fit/arrow_least_squares.hpp"
#include "cyclopt/foot_fit/circle_fit_start.hpp"

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace cyclopt::foot_fit {

// Box on the shape parameters, in the order of foot::parameter_layout(model).
struct FitBounds {
  foot::FootParameters<double> lower, upper;
};

// The seed's bounds: (4.13) for HM, (4.18) for HMT (l_MT <= z_min, gamma_F <= pi/2), with
// k_H = k_M (= k_T) fixed at 1e-8 rad. Where the seed writes k >= 0 the bound is 1e-8: the
// regularisation tanh(a/k) needs k > 0.
FitBounds seed_bounds(foot::FootModel model, double z_min);

// `bounds` widened, parameter by parameter, to [min(lower, p/2), max(upper, 2p)] where p lies
// outside: for refitting a known foot (synthetic ground truth) that the seed's box excludes.
FitBounds widened_to_contain(FitBounds bounds, const foot::FootParameters<double>& p);

// The residual function of eq. (4.16) / (4.21) for the arrow solver: globals = [p (layout
// order), x_off,1..K], locals = all theta_F,k,j trial by trial. Exact Jacobian: derivatives by
// p from Dual<2> per transition (delta_i, k_i; F is linear in l_i) chained with the profile's
// d(l, delta, k)/dp in Dual<9>, by theta from F' and F''.
ArrowResidual rolling_ankle_residual(foot::FootModel model, const std::vector<AnkleTrack>& tracks);

struct ParameterEstimate {
  std::string name, unit;
  double value = 0.0, lower = 0.0, upper = 0.0;
  double standard_error = 0.0;  // from sigma^2 (J^T J)^-1 of the reduced problem; NaN if held
  bool fixed = false;           // lower == upper
  bool at_bound = false;        // held on a bound at the solution
  // Empirical spreads (fit_spread.hpp), NaN until estimated: over the strides (jackknife
  // standard error) and over the stance boundaries (largest change); `flag` says why the
  // parameter is not well determined, empty when nothing is wrong.
  double stride_spread = std::numeric_limits<double>::quiet_NaN();
  double boundary_spread = std::numeric_limits<double>::quiet_NaN();
  std::string flag;
};

struct TrialResidual {
  std::string source;
  int samples = 0;
  double rms = 0.0, max = 0.0;  // m, distance of measured and model ankle
};

struct ConvexityCheck {
  std::vector<std::string> names;  // eq. (3.21) / (3.24) rows and, for HMT, the toe margin
  std::vector<double> values;      // each must be >= 0 (the toe margin > 0)
  bool convex = false;
};

struct FootFitResult {
  foot::FootModel model = foot::FootModel::hm;
  foot::FootParameters<double> parameters;
  std::vector<ParameterEstimate> estimates;
  std::vector<Eigen::VectorXd> theta;  // fitted foot angles per trial and sample (rad)
  std::vector<double> x_off;           // m per trial
  int samples = 0;
  int unknowns = 0;                    // free parameters + angles + offsets
  double rms = 0.0, max_residual = 0.0;  // m over all samples
  double noise_estimate = 0.0;         // m per coordinate, sqrt(|r|^2 / (2N - unknowns))
  std::vector<TrialResidual> trials;
  ConvexityCheck convexity;
  bool converged = false;
  int iterations = 0;
  std::string message;
  double seconds = 0.0;
  // The refits behind the estimates' spreads (fit_spread.hpp): how many count and how many of
  // them stopped unconverged; the boundary tolerance (s). 0, 0, NaN until estimated.
  int spread_refits = 0, spread_unconverged = 0;
  double boundary_tolerance = std::numeric_limits<double>::quiet_NaN();

  foot::FootSpec spec(const std::string& name = {}) const;
  // Model ankle [x, z] of sample j of trial k at the fitted angle (eq. 4.15 / 4.20).
  Eigen::Vector2d model_ankle(int k, int j) const;
};

struct FootFitOptions {
  ArrowOptions solver;
  std::optional<FitBounds> hm_bounds;   // default seed_bounds(hm, z_min)
  std::optional<FitBounds> hmt_bounds;  // default seed_bounds(hmt, z_min)
  bool toe_bound = true;                // false: the default HMT box without l_MT <= z_min (4.18b)
};

// The HM fit (4.16) from the circle-fit start (k_HM = 0.1, section 4.2).
FootFitResult fit_hm(const std::vector<AnkleTrack>& tracks, const CircleFitStart& start, const FootFitOptions& options = {});
// The HMT fit (4.21) from an HM result: the seed's start (k_MT = k_HM, l_MT = l_HM / 10, gamma_F = pi / 6)
// and two starts from the HM solution embedded in HMT; the best is kept, never worse than `hm`.
// seconds and iterations are summed over the three solves.
FootFitResult fit_hmt(const std::vector<AnkleTrack>& tracks, const FootFitResult& hm, double z_min,
                      const FootFitOptions& options = {});

struct RollingFootFit {
  CircleFitStart start;
  FootFitResult hm, hmt;
};
// The seed's three steps in order.
RollingFootFit fit_rolling_foot(const std::vector<AnkleTrack>& tracks, const FootFitOptions& options = {});

}  // namespace cyclopt::foot_fit
