// Dual numbers against hand-derived derivatives and central differences.
#include "cyclopt/autodiff/dual.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <functional>

namespace {
using cyclopt::ad::Dual;
using D2 = Dual<2>;

// A function exercising every elementary operation the core uses.
template <class T>
T mix(const T& x, const T& y) {
  using std::atan2, std::cos, std::exp, std::log, std::sin, std::sqrt, std::tanh, std::atan, std::pow;
  return sin(x) * cos(y) + tanh(x / y) - exp(0.3 * x) / (1.0 + y * y) + log(2.0 + x * x) +
         sqrt(1.0 + y * y) * atan(x - y) + atan2(y, x) + pow(1.5 + x * x, 1.7) - 3.0 / (2.0 + x);
}

TEST(Dual, GradientMatchesCentralDifferences) {
  for (double x : {-1.3, -0.2, 0.4, 2.1}) {
    for (double y : {-2.0, 0.7, 1.9}) {
      const D2 f = mix(D2::variable(x, 0), D2::variable(y, 1));
      EXPECT_NEAR(f.v, mix(x, y), 1e-13 * (1 + std::abs(f.v)));
      // 6th-order central differences, error ~h^6 ~ 1e-12 at h=1e-2
      auto cd = [&](const std::function<double(double)>& g) {
        const double h = 1e-2;
        return (g(3 * h) - 9 * g(2 * h) + 45 * g(h) - 45 * g(-h) + 9 * g(-2 * h) - g(-3 * h)) / (60 * h);
      };
      const double dx = cd([&](double h) { return mix(x + h, y); });
      const double dy = cd([&](double h) { return mix(x, y + h); });
      EXPECT_NEAR(f.d[0], dx, 1e-9 * (1 + std::abs(dx)));
      EXPECT_NEAR(f.d[1], dy, 1e-9 * (1 + std::abs(dy)));
    }
  }
}

TEST(Dual, EigenLinearSolveDifferentiatesTheSolution) {
  // d/dp of A(p)^{-1} b equals -A^{-1} (dA/dp) A^{-1} b.
  const double p = 0.7;
  Eigen::Matrix<Dual<1>, 2, 2> A;
  const Dual<1> pd = Dual<1>::variable(p, 0);
  A << 2.0 + pd, 1.0, pd * pd, 3.0;
  Eigen::Matrix<Dual<1>, 2, 1> b(1.0, 2.0);
  const Eigen::Matrix<Dual<1>, 2, 1> x = A.partialPivLu().solve(b);

  Eigen::Matrix2d Av;
  Av << 2.0 + p, 1.0, p * p, 3.0;
  Eigen::Matrix2d dA;
  dA << 1.0, 0.0, 2 * p, 0.0;
  const Eigen::Vector2d xv = Av.partialPivLu().solve(Eigen::Vector2d(1.0, 2.0));
  const Eigen::Vector2d dx = -Av.partialPivLu().solve(dA * xv);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(x[i].v, xv[i], 1e-15);
    EXPECT_NEAR(x[i].d[0], dx[i], 1e-14);
  }
}
}  // namespace
