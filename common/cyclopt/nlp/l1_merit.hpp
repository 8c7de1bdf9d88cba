#pragma once
// The exact l1 penalty function and its quadratic model, with one penalty weight per constraint
// (seed 001, section 6.2.1). Simple bounds are not penalised: the SQP keeps its iterates inside them.

#include "cyclopt/nlp/problem.hpp"

#include <Eigen/Core>

namespace cyclopt::nlp {

struct Penalties {
  Eigen::VectorXd equality;    // mu_g, one per equality, >= 0
  Eigen::VectorXd inequality;  // mu_u, one per inequality, >= 0
  double max() const;          // mu_max of eq. (6.9); 0 without constraints
  static Penalties uniform(double mu, Eigen::Index m_eq, Eigen::Index m_in);  // eq. (6.10) assignment
};

// phi_1(x, mu) = f + sum mu_g |c_g| + sum mu_u max(0, c_u), eq. (6.6).
double l1_merit(const Evaluation& e, const Penalties& mu);

// m_k(d) = sum |J_g d + c_g| + sum max(0, J_u d + c_u), eq. (6.11). Needs derivatives.
double linearized_violation(const Evaluation& e, const Eigen::VectorXd& d);

// q_k(d, mu) = f + grad f d + 1/2 d'Wd + sum mu_g |J_g d + c_g| + sum mu_u max(0, J_u d + c_u),
// eq. (6.8) (eq. (6.12) when all weights are equal). Needs derivatives.
double l1_model(const Evaluation& e, const Eigen::MatrixXd& W, const Eigen::VectorXd& d, const Penalties& mu);

// The same with the kinked terms near their kink modelled as the subproblem of issue 52 does
// (sqp_subproblems.hpp): grad f' d replaced by (grad f - sum a_s grad p_s)' d
// + sum w_s (max(p_s + grad p_s' d, 0) - max(p_s, 0)). Equal to (6.8) for d = 0.
double l1_model(const Evaluation& e, const Eigen::MatrixXd& W, const Eigen::VectorXd& d, const Penalties& mu,
                const NearKinks& kinks);

}  // namespace cyclopt::nlp
