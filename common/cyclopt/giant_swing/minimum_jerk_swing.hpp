#pragma once
// Part B of issue 6 solved: the minimum-jerk giant swing on the Bezier virtual constraint
// (minimum_jerk_problem.hpp) through the common NLP interface (nlp::solve, Ipopt by default).
//
// Start point: the pike shape (0 .. 0, 1 .. 1) scaled by Newton on its amplitude until the boundary
// equality phi'(2 pi) = omega holds (scale_to_close), so the solver starts on a closed swing.
// Integrations are counted over the whole solve (start point included); an integration with
// sensitivities (ad::Dual<n>) counts as one.

#include "cyclopt/giant_swing/minimum_jerk_problem.hpp"
#include "cyclopt/nlp/solver_options.hpp"

#include <string>

namespace cyclopt::giant_swing {

// Ipopt, exact first derivatives, tolerances that leave |phi'/omega - 1| <= 1e-10.
nlp::SolverOptions minimum_jerk_solver_options();

struct MinimumJerkSettings {
  MinimumJerkProblemOptions problem;
  nlp::SolverOptions solver = minimum_jerk_solver_options();
};

// A result counts as closed when |phi'(2 pi) / omega - 1| stays below this.
inline constexpr double kBoundaryTolerance = 1e-8;

struct MinimumJerkResult {
  bool ok = false;                 // solver success and the boundary equality within tolerance
  std::string message;             // why not, if !ok
  Eigen::VectorXd coefficients;    // the free Bezier coefficients c3..c(n+2), rad
  double jerk = 0.0;               // 1/2 int alpha'''^2 dt on the reduced model (eq. 4.12)
  double boundary_error = 0.0;     // phi'(2 pi) / omega - 1
  double friction_loss = 0.0;      // J, int -M_R phi' dt
  double torque_integral = 0.0;    // Nm^2 s, 1/2 int M_alpha^2 dt
  double start_jerk = 0.0;         // jerk of the closed start swing
  nlp::SolverSummary summary;
  int integrations = 0;            // model integrations, start point included
  double wall_seconds = 0.0;
};

// The pike start shape with n free coefficients: 0 in the first half, 1 in the second.
Eigen::VectorXd pike_shape(int free_coefficients);

// Throws std::invalid_argument for invalid settings (naming the field).
MinimumJerkResult solve_minimum_jerk(const Model& model, const TaskSpec& spec, const MinimumJerkSettings& settings = {});

}  // namespace cyclopt::giant_swing
