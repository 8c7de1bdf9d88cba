#pragma once
// Automatic starting gaits (the seed found its first one by trial, section 8.1) and the random
// perturbation sampler for multistart.
//
// starting_gait(): 1. scan a grid of GaitShape templates (contact distance, torso lean, swing-knee
// bump, push-off rate), keep those with a real periodic solution (eq. 5.87), rank them by
// speed error and constraint violation; 2. from the best templates, restore feasibility in the
// gait parameters x by Levenberg-Marquardt on the residuals [c_g; max(c_u + margin, 0)]
// (eq. 5.103-5.104) with exact Jacobians, every trial step that loses the real solution rejected.
// The result is a real periodic gait at the requested speed; `feasible` says whether all 10P+3
// inequalities hold as well.

#include "cyclopt/nlp/levenberg_marquardt.hpp"
#include "cyclopt/walker/gait_evaluation.hpp"
#include "cyclopt/walker/gait_shape.hpp"

#include <optional>
#include <random>
#include <string>

namespace cyclopt::walker {

struct StartingGaitOptions {
  double speed = 1.3;          // m/s
  double margin = 1e-3;        // inequalities restored to c_u <= -margin (scaled units of 5.104)
  int max_candidates = 6;      // templates tried with Levenberg-Marquardt
  nlp::LeastSquaresOptions least_squares{.max_iterations = 40, .cost_tolerance = 1e-14};
};

struct StartingGait {
  bool real = false;          // x gives a real periodic solution
  bool feasible = false;      // ... with |c_g| <= 1e-8 and c_u <= 0
  Eigen::VectorXd x;
  PeriodicGait<double> gait;
  GaitShape shape;            // template the gait was restored from
  double speed_error = 0.0;   // c_g (m/s)
  double max_violation = 0.0; // max(c_u) (scaled units), <= 0 when feasible
  int evaluations = 0;        // gait evaluations spent (values and Jacobians)
  std::string message;
};

StartingGait starting_gait(const GaitEvaluator& evaluator, const StartingGaitOptions& options);

// Where a solve starts: the given gait parameters, or the automatic starting gait at `speed`.
struct GaitStart {
  Eigen::VectorXd x;
  std::string origin;  // "given" or the starting gait's message
};
// Throws std::runtime_error when there is no given start and no real starting gait.
GaitStart gait_start(const GaitEvaluator& evaluator, double speed, const std::optional<Eigen::VectorXd>& given);

// A random gait near x for multistart: x + scale * N(0, 1) per entry, redrawn until the periodic
// solution is real (at most max_draws draws; throws std::runtime_error naming the scale otherwise).
Eigen::VectorXd perturbed_gait(const GaitEvaluator& evaluator, const Eigen::VectorXd& x, double scale,
                               std::mt19937_64& rng, int max_draws = 1000);

}  // namespace cyclopt::walker
