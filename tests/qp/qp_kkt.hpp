#pragma once
// KKT residuals of a QP solution (sign convention of active_set_solver.hpp), shared by the QP tests.
#include "cyclopt/qp/active_set_solver.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cyclopt::qp::testing {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using cyclopt::qp::QpSolution;
using cyclopt::qp::QpStatus;
using cyclopt::qp::QuadraticProgram;

struct KktResiduals {
  double primal = 0, stationarity = 0, dual = 0, complementarity = 0;
};

inline KktResiduals kkt_residuals(const QuadraticProgram& qp, const QpSolution& s) {
  const Eigen::Index n = qp.num_variables();
  KktResiduals r;
  VectorXd lower = qp.lower_bounds.size() ? qp.lower_bounds : VectorXd::Constant(n, -std::numeric_limits<double>::infinity());
  VectorXd upper = qp.upper_bounds.size() ? qp.upper_bounds : VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  VectorXd stationarity = qp.hessian * s.x + qp.gradient - s.lower_bound_multipliers + s.upper_bound_multipliers;
  if (qp.equality_matrix.rows()) {
    r.primal = std::max(r.primal, (qp.equality_matrix * s.x - qp.equality_rhs).lpNorm<Eigen::Infinity>());
    stationarity += qp.equality_matrix.transpose() * s.equality_multipliers;
  }
  if (qp.inequality_matrix.rows()) {
    const VectorXd slack = qp.inequality_matrix * s.x - qp.inequality_rhs;
    r.primal = std::max(r.primal, slack.maxCoeff());
    stationarity += qp.inequality_matrix.transpose() * s.inequality_multipliers;
    r.dual = std::max(r.dual, -s.inequality_multipliers.minCoeff());
    r.complementarity = std::max(r.complementarity, s.inequality_multipliers.cwiseProduct(slack).cwiseAbs().maxCoeff());
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    r.primal = std::max({r.primal, lower[i] - s.x[i], s.x[i] - upper[i]});
    r.dual = std::max({r.dual, -s.lower_bound_multipliers[i], -s.upper_bound_multipliers[i]});
    if (std::isfinite(lower[i]))
      r.complementarity = std::max(r.complementarity, std::abs(s.lower_bound_multipliers[i] * (s.x[i] - lower[i])));
    else
      r.complementarity = std::max(r.complementarity, std::abs(s.lower_bound_multipliers[i]));
    if (std::isfinite(upper[i]))
      r.complementarity = std::max(r.complementarity, std::abs(s.upper_bound_multipliers[i] * (upper[i] - s.x[i])));
    else
      r.complementarity = std::max(r.complementarity, std::abs(s.upper_bound_multipliers[i]));
  }
  r.stationarity = stationarity.lpNorm<Eigen::Infinity>();
  return r;
}

inline void expect_kkt(const QuadraticProgram& qp, const QpSolution& s, double tol) {
  ASSERT_EQ(s.status, QpStatus::optimal) << s.message;
  const KktResiduals r = kkt_residuals(qp, s);
  EXPECT_LE(r.primal, tol);
  EXPECT_LE(r.stationarity, tol);
  EXPECT_LE(r.dual, tol);
  EXPECT_LE(r.complementarity, tol);
}

}  // namespace cyclopt::qp::testing
