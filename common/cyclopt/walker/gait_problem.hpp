#pragma once
// The walker's optimisation problem of seed 001 section 5.4 as an nlp::Problem:
//
//   min_z f(z)  s.t.  c_g(z) = 0 (5.103),  c_u(z) <= 0 (5.104),  z = [x; p_free],
//
// where x = alpha_tilde are the gait parameters (5.92) and p_free an optional, named subset of the
// model parameters p_mod (5.91) optimised together with the gait (foot-geometry co-optimisation,
// section 10.2). Free foot parameters add the convexity conditions (3.21 / 3.24, and the HMT toe
// margin) as inequalities and their admissible ranges as bounds; with design_bounds also the
// dimension bounds of eq. (10.1). A gait without a real periodic
// solution (5.87) is an evaluation failure, which every solver treats as "step too long".

#include "cyclopt/foot/convexity_constraints.hpp"
#include "cyclopt/foot/design_bounds.hpp"
#include "cyclopt/nlp/problem.hpp"
#include "cyclopt/walker/gait_evaluation.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace cyclopt::walker {

// Largest admissible GaitProblemOptions::positive_power_band (W): joint powers of a walking gait are
// tens of W, so a wider band would change f_mech itself.
inline constexpr double kMaxPositivePowerBand = 1.0;
// Largest admissible GaitProblemOptions::positive_power_smoothing (W): the first stage of the
// smoothing homotopy (smoothing_homotopy.hpp) smooths over the joint powers' own scale.
inline constexpr double kMaxPositivePowerSmoothing = 100.0;

struct GaitProblemOptions {
  Objective objective = Objective::mechanical;
  double speed = 1.3;                          // v_bar (m/s)
  Quadrature quadrature = Quadrature::trapezoid;
  std::vector<std::string> free_parameters;    // names from model_parameter_names(), e.g. {"l_HM", "k_HM"}
  std::optional<foot::DesignBounds> design_bounds = std::nullopt;  // eq. (10.1) rows, with free foot parameters
  double positive_power_band = 0.0;  // W, GaitOptions::positive_power_band, in [0, kMaxPositivePowerBand]; > 0
                                     // needs the trapezoid rule
  double positive_power_smoothing = 0.0;  // W, GaitOptions::positive_power_smoothing, in
                                          // [0, kMaxPositivePowerSmoothing]; > 0 needs the trapezoid rule and no band
};

// The options of one gait evaluation of the problem `o` (objective, speed, quadrature, band).
GaitOptions gait_options_of(const GaitProblemOptions& o, bool keep_trajectories);

class GaitProblem : public nlp::Problem {
 public:
  // Throws std::invalid_argument naming an unknown free parameter (with the valid names) or a
  // positive_power_band or positive_power_smoothing outside its range.
  GaitProblem(const WalkerModel<double>& model, GaitProblemOptions options);

  int num_variables() const override;
  int num_equalities() const override { return 1; }
  int num_inequalities() const override;
  Eigen::VectorXd lower_bounds() const override;
  Eigen::VectorXd upper_bounds() const override;
  nlp::EvaluationStatus evaluate(const Eigen::VectorXd& z, bool with_derivatives, nlp::Evaluation& out) override;
  // evaluate() that also hands back the gait evaluation it rests on (joint powers, interval
  // durations, step length; with derivatives the joint powers' Jacobian).
  nlp::EvaluationStatus evaluate(const Eigen::VectorXd& z, bool with_derivatives, nlp::Evaluation& out, GaitEvaluation& gait);
  std::unique_ptr<nlp::Problem> clone() const override { return std::make_unique<GaitProblem>(*this); }
  std::string variable_name(int i) const override;
  std::string constraint_name(bool equality, int i) const override;

  // z from gait parameters x and the model's current values of the free parameters, and back.
  Eigen::VectorXd initial_point(const Eigen::VectorXd& x) const;
  Eigen::VectorXd gait_parameters(const Eigen::VectorXd& z) const { return z.head(gait_count_); }
  int gait_parameter_count() const { return gait_count_; }
  // The model with the free parameters taken from z.
  WalkerModel<double> model_at(const Eigen::VectorXd& z) const;
  // The full gait (with trajectories) at z.
  PeriodicGait<double> gait_at(const Eigen::VectorXd& z) const;
  // The objective at z on a grid `factor` (>= 1) times finer in theta than the model's P (5.93),
  // which keeps every point of the P grid; NaN where z has no real gait there. An optimum whose
  // objective moves much under refinement exploits the quadrature (studies/design_class.hpp).
  double refined_objective(const Eigen::VectorXd& z, int factor) const;
  const GaitProblemOptions& options() const { return options_; }
  // Evaluations with derivatives carry f_mech's kinked terms (power_kinks.hpp) for solvers that model
  // them (nlp::KinkOptions): with the seed's rule for f_mech - the trapezoid rule with zero crossing,
  // no positive_power_band or positive_power_smoothing (which round the kinks away).
  bool declares_kinks() const {
    return options_.objective == Objective::mechanical && options_.quadrature == Quadrature::trapezoid &&
           options_.positive_power_band == 0.0 && options_.positive_power_smoothing == 0.0;
  }

 private:
  GaitOptions gait_options(bool trajectories) const;
  int foot_constraint_count() const;

  WalkerModel<double> model_;
  GaitEvaluator evaluator_;  // at the base model; rebuilt per evaluation when parameters are free
  GaitProblemOptions options_;
  int gait_count_ = 0;
  std::vector<int> free_indices_;       // into p_mod
  std::vector<std::string> parameter_names_;
  foot::LinearInequalities foot_rows_;  // (3.21 / 3.24) and (10.1), only with free foot parameters
  bool toe_margin_ = false;
};

}  // namespace cyclopt::walker
