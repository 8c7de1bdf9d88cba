#pragma once
// One call that every optimiser and the service use: evaluate a periodic gait at the gait
// parameters x (and optionally perturbed model parameters), with the dense Jacobian of objective
// and constraints from forward-mode automatic differentiation. Directions along x alone keep the
// model double, so every grid point is differentiated locally in double and chained
// (grid_point.hpp); for the default Bezier degree (20 or 30 gait parameters) one pass with
// ad::Dual<n_x padded to 24 or 32> carries every direction, otherwise, and with free model
// parameters (whose chunks cast the model to Dual), chunks of ad::Dual<kJacobianChunk> directions.

#include "cyclopt/walker/model_parameters.hpp"
#include "cyclopt/walker/periodic_gait.hpp"

#include <vector>

namespace cyclopt::walker {

inline constexpr int kJacobianChunk = 8;

// Derivatives of every scalar output with respect to the chosen directions: first the gait
// parameters x (all of them), then the model parameters listed in `parameter_indices`.
struct GaitDerivatives {
  Eigen::RowVectorXd objective, f_mech, f_usq, speed_equality, step_length, step_period, mean_speed, floquet;
  Eigen::MatrixXd inequalities;  // (10P+3) x directions
  Eigen::MatrixXd joint_power;   // (n_b P) x directions, row j P + i: joint j at grid point i (PeriodicGait::joint_power)
  // All rows in the order above: 8 scalar rows, then the inequalities.
  Eigen::MatrixXd stacked() const;
};

struct GaitEvaluation {
  PeriodicGait<double> gait;
  bool has_derivatives = false;
  GaitDerivatives derivatives;
};

// A walker scene ready to evaluate: the model and the Bezier basis for its (M, P).
class GaitEvaluator {
 public:
  explicit GaitEvaluator(WalkerModel<double> model);
  const WalkerModel<double>& model() const { return model_; }
  const BezierBasis& basis() const { return basis_; }
  int parameter_count() const { return gait_parameter_count(model_.joint_count, model_.constants.bezier_degree); }

  // Values only.
  PeriodicGait<double> evaluate(const Eigen::VectorXd& x, const GaitOptions& options) const;
  // Values and derivatives with respect to x and the listed model parameters (indices into p_mod).
  // Where the value pass finds a gait but the derivative pass, on the boundary of existence, does
  // not, the result has gait.real = false with both passes' reason, like a point without a gait.
  GaitEvaluation evaluate_with_derivatives(const Eigen::VectorXd& x, const GaitOptions& options,
                                           const std::vector<int>& parameter_indices = {}) const;
  // The same derivatives by the plain reference path: chunks of ad::Dual<kJacobianChunk> with the
  // whole model cast to Dual (its constants carrying zero derivatives). For checks and benchmarks.
  GaitEvaluation evaluate_with_reference_derivatives(const Eigen::VectorXd& x, const GaitOptions& options,
                                                     const std::vector<int>& parameter_indices = {}) const;

 private:
  enum class DerivativePath { fast, reference };
  GaitEvaluation derivatives(const Eigen::VectorXd& x, const GaitOptions& options, const std::vector<int>& parameter_indices,
                             DerivativePath path) const;

  WalkerModel<double> model_;
  BezierBasis basis_;
};

}  // namespace cyclopt::walker
