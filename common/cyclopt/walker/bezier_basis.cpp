#include "cyclopt/walker/bezier_basis.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cyclopt::walker {

namespace {

double binomial(int n, int k) {
  if (k < 0 || k > n) return 0.0;
  double r = 1.0;
  for (double i = 1.0; i <= k; i += 1.0) r = r * (n - k + i) / i;
  return r;
}

// Bernstein polynomial b_i,n(s); zero outside 0 <= i <= n.
double bernstein(int i, int n, double s) {
  if (i < 0 || i > n) return 0.0;
  return binomial(n, i) * std::pow(s, i) * std::pow(1.0 - s, n - i);
}

}  // namespace

Eigen::Matrix<double, Eigen::Dynamic, 3> bezier_basis_at(int M, double s) {
  Eigen::Matrix<double, Eigen::Dynamic, 3> b(M + 1, 3);
  for (int i = 0; i <= M; ++i) {
    b(i, 0) = bernstein(i, M, s);
    // d/ds b_i,M = M (b_{i-1,M-1} - b_{i,M-1}); applied twice for the second derivative (eq. 5.51-5.52)
    b(i, 1) = M * (bernstein(i - 1, M - 1, s) - bernstein(i, M - 1, s));
    b(i, 2) = M * (M - 1) *
              (bernstein(i - 2, M - 2, s) - 2.0 * bernstein(i - 1, M - 2, s) + bernstein(i, M - 2, s));
  }
  return b;
}

BezierBasis bezier_basis(int degree, int points) {
  if (degree < 2) throw std::invalid_argument("bezier_degree: " + std::to_string(degree) + " outside [2, 12]");
  if (points < 2) throw std::invalid_argument("points: " + std::to_string(points) + " outside [2, 100000]");
  BezierBasis B;
  B.degree = degree;
  B.s = Eigen::VectorXd::LinSpaced(points, 0.0, 1.0);
  B.value.resize(degree + 1, points);
  B.first.resize(degree + 1, points);
  B.second.resize(degree + 1, points);
  for (int k = 0; k < points; ++k) {
    const auto b = bezier_basis_at(degree, B.s(k));
    B.value.col(k) = b.col(0);
    B.first.col(k) = b.col(1);
    B.second.col(k) = b.col(2);
  }
  return B;
}

}  // namespace cyclopt::walker
