#pragma once
// Test NLPs written once as scalar templates: values with double, exact first derivatives with
// cyclopt::ad::Dual<n>. A definition D provides
//   static constexpr int n, m_eq, m_in;
//   template <class T> static void evaluate(const T* x, T& f, T* c_eq, T* c_in);
// and optionally `static bool evaluable(const double* x)` (false = "no real solution").

#include "cyclopt/autodiff/dual.hpp"
#include "cyclopt/nlp/problem.hpp"

#include <Eigen/Core>

#include <array>
#include <limits>
#include <string>

namespace cyclopt::nlp::testing {

template <class D>
class AutodiffProblem : public Problem {
 public:
  AutodiffProblem()  // no bounds
      : AutodiffProblem(Eigen::VectorXd::Constant(D::n, -std::numeric_limits<double>::infinity()),
                        Eigen::VectorXd::Constant(D::n, std::numeric_limits<double>::infinity())) {}
  AutodiffProblem(Eigen::VectorXd lower, Eigen::VectorXd upper) : lower_(std::move(lower)), upper_(std::move(upper)) {}
  int num_variables() const override { return D::n; }
  int num_equalities() const override { return D::m_eq; }
  int num_inequalities() const override { return D::m_in; }
  Eigen::VectorXd lower_bounds() const override { return lower_; }
  Eigen::VectorXd upper_bounds() const override { return upper_; }

  EvaluationStatus evaluate(const Eigen::VectorXd& x, bool with_derivatives, Evaluation& out) override {
    if constexpr (requires { D::evaluable(x.data()); }) {
      if (!D::evaluable(x.data())) return EvaluationStatus::failure("no real solution");
    }
    out.equalities.resize(D::m_eq);
    out.inequalities.resize(D::m_in);
    if (!with_derivatives) {
      std::array<double, D::m_eq + 1> eq{};
      std::array<double, D::m_in + 1> in{};
      D::evaluate(x.data(), out.objective, eq.data(), in.data());
      for (int i = 0; i < D::m_eq; ++i) out.equalities[i] = eq[static_cast<size_t>(i)];
      for (int i = 0; i < D::m_in; ++i) out.inequalities[i] = in[static_cast<size_t>(i)];
      return EvaluationStatus::success();
    }
    using Dual = ad::Dual<D::n>;
    std::array<Dual, D::n> xd;
    for (int i = 0; i < D::n; ++i) xd[static_cast<size_t>(i)] = Dual::variable(x[i], i);
    Dual f;
    std::array<Dual, D::m_eq + 1> eq{};
    std::array<Dual, D::m_in + 1> in{};
    D::evaluate(xd.data(), f, eq.data(), in.data());
    out.objective = f.v;
    out.gradient = f.d;
    out.equality_jacobian.resize(D::m_eq, D::n);
    out.inequality_jacobian.resize(D::m_in, D::n);
    for (int i = 0; i < D::m_eq; ++i) {
      out.equalities[i] = eq[static_cast<size_t>(i)].v;
      out.equality_jacobian.row(i) = eq[static_cast<size_t>(i)].d.transpose();
    }
    for (int i = 0; i < D::m_in; ++i) {
      out.inequalities[i] = in[static_cast<size_t>(i)].v;
      out.inequality_jacobian.row(i) = in[static_cast<size_t>(i)].d.transpose();
    }
    return EvaluationStatus::success();
  }

 private:
  Eigen::VectorXd lower_, upper_;
};

}  // namespace cyclopt::nlp::testing
