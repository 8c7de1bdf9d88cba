#pragma once
// A dense convex quadratic program
//
//   min_x 1/2 x'Hx + g'x   subject to   A_eq x = b_eq,   A_in x <= b_in,   lower <= x <= upper,
//
// with H symmetric positive SEMI-definite (the l1-relaxed SQP subproblem, seed 001 eq. (6.13),
// has zero curvature in its slack variables; the LP (6.14) has H = 0).

#include <Eigen/Core>

namespace cyclopt::qp {

struct QuadraticProgram {
  Eigen::MatrixXd hessian;            // H, n x n, symmetric positive semidefinite
  Eigen::VectorXd gradient;           // g, size n (defines n)
  Eigen::MatrixXd equality_matrix;    // A_eq, m_eq x n (0 x n when absent)
  Eigen::VectorXd equality_rhs;       // b_eq, size m_eq
  Eigen::MatrixXd inequality_matrix;  // A_in, m_in x n (0 x n when absent)
  Eigen::VectorXd inequality_rhs;     // b_in, size m_in
  Eigen::VectorXd lower_bounds;       // size n with -inf where free, or empty for "all free"
  Eigen::VectorXd upper_bounds;       // size n with +inf where free, or empty for "all free"

  Eigen::Index num_variables() const { return gradient.size(); }
  double objective(const Eigen::VectorXd& x) const { return 0.5 * x.dot(hessian * x) + gradient.dot(x); }
};

// Throws std::invalid_argument naming the first inconsistent field (sizes, NaN, lower > upper).
void validate(const QuadraticProgram& qp);

}  // namespace cyclopt::qp
