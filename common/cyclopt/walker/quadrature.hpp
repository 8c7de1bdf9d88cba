#pragma once
// Cumulative quadrature on the uniform phase grid of seed 001 eq. (5.93).
//
//   trapezoid (the seed's, footnote 11 of section 5.3):  I_k = h sum_{i<k} (f_i + f_{i+1}) / 2,   O(h^2)
//   corrected trapezoid (Euler-Maclaurin end correction): I_k - h^2/12 (f'_k - f'_0),             O(h^4)
//     with f' from second-order differences of the samples (central inside, one-sided at the ends),
//     so it needs no derivatives of the model and costs O(P) extra additions.
// The corrected rule is only valid for smooth integrands: f_mech (5.100) keeps the trapezoid rule
// with the zero-crossing correction of Fig. 5.3.

#include "cyclopt/walker/walker_model.hpp"

namespace cyclopt::walker {

enum class Quadrature { trapezoid, corrected_trapezoid };

// Running integrals I_0 = 0, ..., I_{P-1} of samples f on a grid with spacing h (P >= 3).
template <class T, class Samples>
Eigen::Matrix<T, Eigen::Dynamic, 1> cumulative_integral(const Samples& f, const T& h, Quadrature rule) {
  const int P = static_cast<int>(f.size());
  Eigen::Matrix<T, Eigen::Dynamic, 1> I(P);
  I(0) = T(0.0);
  for (int i = 1; i < P; ++i) I(i) = I(i - 1) + 0.5 * h * (f(i - 1) + f(i));
  if (rule == Quadrature::corrected_trapezoid && P >= 3) {
    auto slope = [&](int i) -> T {
      if (i == 0) return (-3.0 * f(0) + 4.0 * f(1) - f(2)) / (2.0 * h);
      if (i == P - 1) return (3.0 * f(P - 1) - 4.0 * f(P - 2) + f(P - 3)) / (2.0 * h);
      return (f(i + 1) - f(i - 1)) / (2.0 * h);
    };
    const T d0 = slope(0);
    for (int i = 1; i < P; ++i) I(i) -= h * h / 12.0 * (slope(i) - d0);
  }
  return I;
}

}  // namespace cyclopt::walker
