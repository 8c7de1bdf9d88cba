#pragma once
// Parametric sensitivities of the optimal objective from the KKT point, without a re-solve
// (issue 15 item 6; the first-order counterpart of the +-10 % continuation of seed 001 section
// 10.1, sensitivity.hpp). At a KKT point z* of min f(z; p) s.t. c_g(z; p) = 0 (5.103),
// c_u(z; p) <= 0 (5.104) with multipliers y (equality) and mu >= 0 (inequality) in the sign
// convention of nlp::SolverSummary, the envelope theorem gives
//
//   d f*/d p = dL/dp = df/dp + y' dc_g/dp + mu' dc_u/dp,
//
// with the exact AD columns of p (the problem rebuilt with p appended to z as a free parameter).
// Bounds of z do not depend on p, so bound multipliers do not enter; p itself is fixed.
//
// The formula needs a unique multiplier vector (independent active gradients) and holds on both
// sides of p as long as the active set does not change within the step. Where it changes at p
// itself - a weakly active inequality or bound (c ~ 0 and mu ~ 0) that the linearised solution
// moves into violation on one side, or a strongly active one whose multiplier the linearised
// solution drives through 0 - f*(p) has a kink in its derivative there: df*/dp is still the
// envelope value, but a difference quotient over the step is off by O(step) instead of O(step^2),
// and a larger change (the +-10 % continuation) follows another active set. So each parameter
// also gets, from the linearised KKT system on the strongly active set (Hessian of the Lagrangian
// by differences of the exact gradient), the relative change of p at which the first constraint
// enters or leaves the active set on either side, and which constraint that is.

#include "cyclopt/nlp/solver_options.hpp"
#include "cyclopt/walker/gait_problem.hpp"

#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

namespace cyclopt::studies {

struct KktSensitivityOptions {
  std::vector<std::string> parameters;  // model parameter names; empty: every one neither free nor derived (m_F, r_F, J_F, theta_F0 with a density)
  double active_tolerance = 1e-6;       // c_u >= -tol (or z within tol of a bound): active
  double weak_multiplier = 1e-8;        // an active row with |multiplier| <= this is weakly active
  // A side whose predicted active-set change is nearer than this relative change of p is
  // one-sided (a kink at p): the flag of ParameterSensitivity.
  double kink_range = 1e-6;
};

// Where the linearised optimum changes its active set when p moves one way.
struct ActiveSetChange {
  double relative_change = std::numeric_limits<double>::infinity();  // |p - p0| / |p0| at the change; inf: none predicted
  std::string constraint;                                            // the row (or bound) that enters or leaves; empty: none
  bool enters = false;                                               // true: becomes active; false: its multiplier reaches 0
};

struct ParameterSensitivity {
  std::string name;
  double value = 0.0;
  double derivative = 0.0;  // d f*/d p (5.102 or 5.101 per unit of p)
  double relative = 0.0;    // p / f* d f*/d p
  ActiveSetChange decrease, increase;
  bool kink = false;        // one side changes the active set at p: a one-sided (second-order) kink
  std::vector<std::string> weakly_active;  // the weakly active rows behind a kink
};

struct KktSensitivity {
  double objective = 0.0;
  double lagrangian_gradient = 0.0;  // |grad_z L|_inf with the given multipliers: how good the KKT point is
  int active_constraints = 0;        // strongly active rows incl. c_g and bounds
  std::vector<std::string> weakly_active;  // every weakly active row and bound at the point
  bool unique_multipliers = true;    // false: the active gradients are dependent (the formula picks one multiplier set)
  std::vector<ParameterSensitivity> parameters;
  double seconds = 0.0;
};

// model and problem: the problem as solved (with its own free parameters); z and the multipliers
// from its SolverSummary (an optimum; not checked here beyond the sizes). Throws
// std::invalid_argument for an unknown, free or derived parameter, mismatched sizes, or a point
// that cannot be evaluated.
KktSensitivity kkt_sensitivity(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                               const Eigen::VectorXd& z, const nlp::SolverSummary& multipliers,
                               const KktSensitivityOptions& options = {});

// The parameters kkt_sensitivity covers by default.
std::vector<std::string> sensitivity_parameters(const walker::WalkerModel<double>& model,
                                                const walker::GaitProblemOptions& problem);

}  // namespace cyclopt::studies
