#pragma once
// Bernstein basis of the virtual constraints q_b,d(theta) = sum_i alpha_i b_i,M(s) (seed 001
// eq. 5.49-5.52). The grid of eq. (5.93) is uniform in s = (theta - theta+)/(theta- - theta+),
// independent of theta+-, so the basis and its s-derivatives are tabulated once per (M, P):
//   q_b,d = alpha B,  q_b,d' = alpha B_s / (theta- - theta+),  q_b,d'' = alpha B_ss / (theta- - theta+)^2.

#include "cyclopt/autodiff/dual.hpp"

#include <Eigen/Core>

namespace cyclopt::walker {

struct BezierBasis {
  int degree = 0;         // M
  Eigen::VectorXd s;      // grid in [0, 1], P points
  Eigen::MatrixXd value;  // (M+1) x P: b_i,M(s_k)
  Eigen::MatrixXd first;  // d/ds
  Eigen::MatrixXd second; // d^2/ds^2
};

// alpha B for coefficients of any scalar, B one of the tabulated bases, never cast to the
// coefficients' scalar: for Dual coefficients values and derivative parts are each one double
// matrix product (per joint, derivatives x basis).
template <class Coefficients>
Eigen::Matrix<typename Coefficients::Scalar, Eigen::Dynamic, Eigen::Dynamic> bezier_combination(const Coefficients& alpha,
                                                                                              const Eigen::MatrixXd& B) {
  using T = typename Coefficients::Scalar;
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> r(alpha.rows(), B.cols());
  if constexpr (ad::is_dual_v<T>) {
    constexpr int N = decltype(T::d)::RowsAtCompileTime;
    Eigen::MatrixXd values(alpha.rows(), alpha.cols());
    Eigen::Matrix<double, N, Eigen::Dynamic> derivatives(N, alpha.cols());
    for (int j = 0; j < alpha.rows(); ++j) {
      for (int i = 0; i < alpha.cols(); ++i) {
        values(j, i) = alpha(j, i).v;
        derivatives.col(i) = alpha(j, i).d;
      }
      const Eigen::Matrix<double, N, Eigen::Dynamic> rd = derivatives * B;
      for (int k = 0; k < B.cols(); ++k) r(j, k).d = rd.col(k);
    }
    const Eigen::MatrixXd rv = values * B;
    for (int k = 0; k < B.cols(); ++k)
      for (int j = 0; j < alpha.rows(); ++j) r(j, k).v = rv(j, k);
  } else {
    for (int k = 0; k < B.cols(); ++k)
      for (int j = 0; j < alpha.rows(); ++j) {
        T sum = T(0.0);
        for (int i = 0; i < B.rows(); ++i) sum += alpha(j, i) * B(i, k);
        r(j, k) = sum;
      }
  }
  return r;
}

// Basis on P equidistant points of [0, 1] (eq. 5.93); P >= 2, M >= 2.
BezierBasis bezier_basis(int degree, int points);
// Basis at arbitrary s (for forward simulation and plotting): columns of a (M+1) x 3 matrix
// [b, db/ds, d2b/ds2].
Eigen::Matrix<double, Eigen::Dynamic, 3> bezier_basis_at(int degree, double s);

}  // namespace cyclopt::walker
