#pragma once
// The two least-squares projections onto the active constraints of the seed's SQP
// (seed 001, sections 6.2.2 and 6.2.3). "Active" = all equalities, the listed inequalities and
// bounds; both use a rank-revealing (complete orthogonal) decomposition, so linearly dependent
// active constraints are fine.

#include "cyclopt/nlp/problem.hpp"

#include <Eigen/Core>

#include <vector>

namespace cyclopt::nlp {

struct ActiveConstraints {
  std::vector<int> inequalities;  // rows of c_in
  std::vector<int> bounds;        // variables at a lower or upper bound
};

struct LeastSquaresMultipliers {
  Eigen::VectorXd equality;    // size m_eq
  Eigen::VectorXd inequality;  // size m_in, 0 for inactive rows
  Eigen::VectorXd bound;       // size n, 0 for inactive bounds (sign convention of SolverSummary)
};

// eq. (6.26)/(6.27): the multipliers minimising |grad f + J_g' y_g + J_A' y_A + nu|_2 over the
// active set (the seed prints grad f(x_k) in (6.26); (6.27) shows it is grad f(x_{k+1}), the
// point of the evaluation). Needs derivatives.
LeastSquaresMultipliers least_squares_multipliers(const Evaluation& e, const ActiveConstraints& active);

// eq. (6.18): the shortest d_soc with J_g d_soc + c_g = 0 and J_i d_soc + c_i = 0 for the listed
// inequalities (6.17), at the trial point x_k + d_k of the evaluation (with derivatives).
Eigen::VectorXd second_order_correction(const Evaluation& trial, const std::vector<int>& active_inequalities);

// The same with the kinked samples the QP held at their kink (issue 52) as further rows:
// p_s(x_k + d_k) + grad p_s' d_soc = 0, so the correction keeps a held joint held.
Eigen::VectorXd second_order_correction(const Evaluation& trial, const std::vector<int>& active_inequalities,
                                        const std::vector<int>& held_kinks);

}  // namespace cyclopt::nlp
