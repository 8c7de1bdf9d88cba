#pragma once
// Small standard NLPs with known optima: Hock & Schittkowski, "Test Examples for Nonlinear
// Programming Codes" (1981), in the sign convention of nlp::Problem (c_in <= 0).

#include "autodiff_problem.hpp"

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace cyclopt::nlp::testing {

struct TestProblem {
  std::string name;
  std::function<std::unique_ptr<Problem>()> make;
  Eigen::VectorXd x0;      // the published start
  double f_star;           // the published optimum
  Eigen::VectorXd x_star;  // the published minimiser
  double published_digits_tolerance;  // relative precision of f_star / x_star as published
};

constexpr double kInf = std::numeric_limits<double>::infinity();

// Rosenbrock with a (inactive) bound.
struct Hs001 {
  static constexpr int n = 2, m_eq = 0, m_in = 0;
  template <class T> static void evaluate(const T* x, T& f, T*, T*) {
    f = 100.0 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]) + (1.0 - x[0]) * (1.0 - x[0]);
  }
};
struct Hs004 {  // bounds only, both active
  static constexpr int n = 2, m_eq = 0, m_in = 0;
  template <class T> static void evaluate(const T* x, T& f, T*, T*) { f = (x[0] + 1.0) * (x[0] + 1.0) * (x[0] + 1.0) / 3.0 + x[1]; }
};
struct Hs006 {
  static constexpr int n = 2, m_eq = 1, m_in = 0;
  template <class T> static void evaluate(const T* x, T& f, T* eq, T*) {
    f = (1.0 - x[0]) * (1.0 - x[0]);
    eq[0] = 10.0 * (x[1] - x[0] * x[0]);
  }
};
struct Hs007 {
  static constexpr int n = 2, m_eq = 1, m_in = 0;
  template <class T> static void evaluate(const T* x, T& f, T* eq, T*) {
    using std::log;
    f = log(1.0 + x[0] * x[0]) - x[1];
    eq[0] = (1.0 + x[0] * x[0]) * (1.0 + x[0] * x[0]) + x[1] * x[1] - 4.0;
  }
};
struct Hs014 {
  static constexpr int n = 2, m_eq = 1, m_in = 1;
  template <class T> static void evaluate(const T* x, T& f, T* eq, T* in) {
    f = (x[0] - 2.0) * (x[0] - 2.0) + (x[1] - 1.0) * (x[1] - 1.0);
    eq[0] = x[0] - 2.0 * x[1] + 1.0;
    in[0] = x[0] * x[0] / 4.0 + x[1] * x[1] - 1.0;
  }
};
struct Hs021 {
  static constexpr int n = 2, m_eq = 0, m_in = 1;
  template <class T> static void evaluate(const T* x, T& f, T*, T* in) {
    f = 0.01 * x[0] * x[0] + x[1] * x[1] - 100.0;
    in[0] = -(10.0 * x[0] - x[1] - 10.0);
  }
};
struct Hs028 {
  static constexpr int n = 3, m_eq = 1, m_in = 0;
  template <class T> static void evaluate(const T* x, T& f, T* eq, T*) {
    f = (x[0] + x[1]) * (x[0] + x[1]) + (x[1] + x[2]) * (x[1] + x[2]);
    eq[0] = x[0] + 2.0 * x[1] + 3.0 * x[2] - 1.0;
  }
};
struct Hs035 {
  static constexpr int n = 3, m_eq = 0, m_in = 1;
  template <class T> static void evaluate(const T* x, T& f, T*, T* in) {
    f = 9.0 - 8.0 * x[0] - 6.0 * x[1] - 4.0 * x[2] + 2.0 * x[0] * x[0] + 2.0 * x[1] * x[1] + x[2] * x[2] +
        2.0 * x[0] * x[1] + 2.0 * x[0] * x[2];
    in[0] = x[0] + x[1] + 2.0 * x[2] - 3.0;
  }
};
struct Hs039 {
  static constexpr int n = 4, m_eq = 2, m_in = 0;
  template <class T> static void evaluate(const T* x, T& f, T* eq, T*) {
    f = -x[0];
    eq[0] = x[1] - x[0] * x[0] * x[0] - x[2] * x[2];
    eq[1] = x[0] * x[0] - x[1] - x[3] * x[3];
  }
};
struct Hs040 {
  static constexpr int n = 4, m_eq = 3, m_in = 0;
  template <class T> static void evaluate(const T* x, T& f, T* eq, T*) {
    f = -x[0] * x[1] * x[2] * x[3];
    eq[0] = x[0] * x[0] * x[0] + x[1] * x[1] - 1.0;
    eq[1] = x[0] * x[0] * x[3] - x[2];
    eq[2] = x[3] * x[3] - x[1];
  }
};
struct Hs048 {
  static constexpr int n = 5, m_eq = 2, m_in = 0;
  template <class T> static void evaluate(const T* x, T& f, T* eq, T*) {
    f = (x[0] - 1.0) * (x[0] - 1.0) + (x[1] - x[2]) * (x[1] - x[2]) + (x[3] - x[4]) * (x[3] - x[4]);
    eq[0] = x[0] + x[1] + x[2] + x[3] + x[4] - 5.0;
    eq[1] = x[2] - 2.0 * (x[3] + x[4]) + 3.0;
  }
};
struct Hs071 {
  static constexpr int n = 4, m_eq = 1, m_in = 1;
  template <class T> static void evaluate(const T* x, T& f, T* eq, T* in) {
    f = x[0] * x[3] * (x[0] + x[1] + x[2]) + x[2];
    eq[0] = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3] - 40.0;
    in[0] = 25.0 - x[0] * x[1] * x[2] * x[3];
  }
};
struct Hs076 {
  static constexpr int n = 4, m_eq = 0, m_in = 3;
  template <class T> static void evaluate(const T* x, T& f, T*, T* in) {
    f = x[0] * x[0] + 0.5 * x[1] * x[1] + x[2] * x[2] + 0.5 * x[3] * x[3] - x[0] * x[2] + x[2] * x[3] - x[0] - 3.0 * x[1] +
        x[2] - x[3];
    in[0] = x[0] + 2.0 * x[1] + x[2] + x[3] - 5.0;
    in[1] = 3.0 * x[0] + x[1] + 2.0 * x[2] - x[3] - 4.0;
    in[2] = -x[1] - 4.0 * x[2] + 1.5;
  }
};
struct Hs100 {
  static constexpr int n = 7, m_eq = 0, m_in = 4;
  template <class T> static void evaluate(const T* x, T& f, T*, T* in) {
    const T x2sq = x[1] * x[1], x5sq = x[4] * x[4];
    f = (x[0] - 10.0) * (x[0] - 10.0) + 5.0 * (x[1] - 12.0) * (x[1] - 12.0) + x[2] * x[2] * x[2] * x[2] +
        3.0 * (x[3] - 11.0) * (x[3] - 11.0) + 10.0 * x5sq * x5sq * x5sq + 7.0 * x[5] * x[5] + x[6] * x[6] * x[6] * x[6] -
        4.0 * x[5] * x[6] - 10.0 * x[5] - 8.0 * x[6];
    in[0] = -(127.0 - 2.0 * x[0] * x[0] - 3.0 * x2sq * x2sq - x[2] - 4.0 * x[3] * x[3] - 5.0 * x[4]);
    in[1] = -(282.0 - 7.0 * x[0] - 3.0 * x[1] - 10.0 * x[2] * x[2] - x[3] + x[4]);
    in[2] = -(196.0 - 23.0 * x[0] - x2sq - 6.0 * x[5] * x[5] + 8.0 * x[6]);
    in[3] = -(-4.0 * x[0] * x[0] - x2sq + 3.0 * x[0] * x[1] - 2.0 * x[2] * x[2] - 5.0 * x[5] + 11.0 * x[6]);
  }
};

inline Eigen::VectorXd vec(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double value : values) v[i++] = value;
  return v;
}

template <class D>
std::function<std::unique_ptr<Problem>()> factory(Eigen::VectorXd lower = Eigen::VectorXd::Constant(D::n, -kInf),
                                                  Eigen::VectorXd upper = Eigen::VectorXd::Constant(D::n, kInf)) {
  return [lower, upper] { return std::make_unique<AutodiffProblem<D>>(lower, upper); };
}

inline std::vector<TestProblem> hock_schittkowski_problems() {
  const double s7 = std::sqrt(7.0);
  return {
      {"HS1", factory<Hs001>(vec({-kInf, -1.5})), vec({-2, 1}), 0.0, vec({1, 1}), 1e-12},
      {"HS4", factory<Hs004>(vec({1, 0})), vec({1.125, 0.125}), 8.0 / 3.0, vec({1, 0}), 1e-12},
      {"HS6", factory<Hs006>(), vec({-1.2, 1}), 0.0, vec({1, 1}), 1e-12},
      {"HS7", factory<Hs007>(), vec({2, 2}), -std::sqrt(3.0), vec({0, std::sqrt(3.0)}), 1e-12},
      {"HS14", factory<Hs014>(), vec({2, 2}), 9.0 - 23.0 * s7 / 8.0, vec({0.5 * (s7 - 1), 0.25 * (s7 + 1)}), 1e-12},
      {"HS21", factory<Hs021>(vec({2, -50}), vec({50, 50})), vec({-1, -1}), -99.96, vec({2, 0}), 1e-12},
      {"HS28", factory<Hs028>(), vec({-4, 1, 1}), 0.0, vec({0.5, -0.5, 0.5}), 1e-12},
      {"HS35", factory<Hs035>(Eigen::VectorXd::Zero(3)), vec({0.5, 0.5, 0.5}), 1.0 / 9.0, vec({4.0 / 3, 7.0 / 9, 4.0 / 9}), 1e-12},
      {"HS39", factory<Hs039>(), vec({2, 2, 2, 2}), -1.0, vec({1, 1, 0, 0}), 1e-12},
      {"HS40", factory<Hs040>(), vec({0.8, 0.8, 0.8, 0.8}), -0.25,
       vec({std::pow(2.0, -1.0 / 3), std::pow(2.0, -0.5), std::pow(2.0, -11.0 / 12), std::pow(2.0, -0.25)}), 1e-12},
      {"HS48", factory<Hs048>(), vec({3, 5, -3, 2, -2}), 0.0, vec({1, 1, 1, 1, 1}), 1e-12},
      {"HS71", factory<Hs071>(Eigen::VectorXd::Constant(4, 1.0), Eigen::VectorXd::Constant(4, 5.0)), vec({1, 5, 5, 1}),
       17.0140173, vec({1, 4.7429994, 3.8211503, 1.3794082}), 1e-7},
      {"HS76", factory<Hs076>(Eigen::VectorXd::Zero(4)), vec({0.5, 0.5, 0.5, 0.5}), -103.0 / 22.0,
       vec({3.0 / 11, 23.0 / 11, 0, 6.0 / 11}), 1e-12},
      {"HS100", factory<Hs100>(), vec({1, 2, 0, 4, 0, 1, 1}), 680.6300573,
       vec({2.330499, 1.951372, -0.4775414, 4.365726, -0.6244870, 1.038131, 1.594227}), 1e-6},
  };
}

}  // namespace cyclopt::nlp::testing
