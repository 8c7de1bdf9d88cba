#pragma once
// Sensitivity of an optimal gait to model parameters by continuation (seed 001, section 10.1,
// Fig. 10.1): each parameter is varied by a finite relative amount (+-10 % in the seed) with the
// QPSQP method from the optimum, in both directions, and the change of the objective Delta f
// along the followed curve is reported. Linearisation would miss the kinks of the nonsmooth
// solution curve; jumps to other curves are reported with the curve ids.
#include "cyclopt/continuation/continuation_options.hpp"
#include "cyclopt/walker/gait_problem.hpp"
#include <string>
#include <vector>

namespace cyclopt::studies {

using continuation::ContinuationOptions;

struct SensitivityOptions {
  std::vector<std::string> parameters;  // model parameter names; empty: all foot parameters
  double relative_range = 0.1;          // +-10 %; in (0, 1)
  int steps = 5;                        // requested values per direction; >= 1
  // Delta_min of Table 7.1 as a fraction of the grid spacing p_0 * relative_range / steps, so
  // that it is in the parameter's units (Table 7.1: 0.002 m/s on a 0.1 m/s speed grid); in (0, 1].
  // It replaces continuation.min_trust_region.
  double min_step_fraction = 0.02;
  ContinuationOptions continuation;
};

struct SensitivityPoint {
  double relative_change = 0.0;   // (p - p_0) / p_0
  double delta_objective = 0.0;   // f(p) - f(p_0)
  int curve_id = 0;               // 0: the curve of the optimum; others after a jump
};

struct SensitivityCurve {
  std::string parameter;
  double base_value = 0.0;
  std::vector<SensitivityPoint> points;  // converged requested values, ascending in p
  int jumps = 0;
  std::string message;                   // why a direction stopped early, empty if both finished
};

// z: an optimum of the problem (GaitProblem variables). Throws std::invalid_argument for unknown
// or zero-valued parameters and invalid options.
std::vector<SensitivityCurve> sensitivity(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                                          const Eigen::VectorXd& z, const SensitivityOptions& options);

}  // namespace cyclopt::studies
