#pragma once
// Bound-constrained linear least squares
//
//   min_x ||A x - b||_2   subject to   lower <= x <= upper   (entries may be -inf / +inf),
//
// by the BVLS method of Stark & Parker ("Bounded-variable least-squares: an algorithm and
// applications", Computational Statistics 10, 1995), the bounded form of Lawson & Hanson's NNLS.
// Variables sit at a bound or are free; a free set's unconstrained least-squares solution (minimum
// norm, so dependent columns are fine) is taken as far as the bounds allow, and the bound variable
// whose gradient points most into its box is freed next. Meant for few rows and many columns, most
// of them at a bound: the multipliers of an optimality test (nlp/clarke_stationarity.hpp: n ~ 30
// rows, a column per active constraint and per sample at the kink of f_mech), where every free set
// spans at most the n rows.

#include <Eigen/Core>

namespace cyclopt::qp {

struct BoundedLeastSquaresOptions {
  // Optimal when no bound variable's descent direction A_j'(b - Ax) / |A_j|_2 points into its box by
  // more than optimality_tolerance * max(1, |b|_2). Admissible: > 0.
  double optimality_tolerance = 1e-12;
  int max_iterations = 10000;  // changes of the free set; admissible: >= 1
};

struct BoundedLeastSquaresSolution {
  bool converged = false;  // false: max_iterations reached (x is feasible, not optimal)
  int iterations = 0;
  Eigen::VectorXd x;
  Eigen::VectorXd residual;  // A x - b
};

// Throws std::invalid_argument naming the inconsistent argument (sizes, NaN, lower > upper).
BoundedLeastSquaresSolution solve_bounded_least_squares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                                       const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                                       const BoundedLeastSquaresOptions& options = {});

}  // namespace cyclopt::qp
