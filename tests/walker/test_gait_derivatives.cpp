// Exact derivatives of the periodic gait (forward-mode AD, ad::Dual) against the complex step on
// the same templated code path (seed 001 section 6.1): >= 100 random feasible gaits for the gait
// parameters x, and every model parameter p_mod (eq. 5.91) for each reference foot.
#include "reference_gaits.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <cstdio>
#include <random>

namespace cyclopt::walker {
namespace {

using C = std::complex<double>;
using testing::kReferenceFeet;
constexpr double kStep = 1e-30;

// All scalar outputs and constraints of a gait, stacked: [f; f_mech; f_usq; c_g; L; T; v; Lambda; c_u].
template <class T>
Eigen::Matrix<T, Eigen::Dynamic, 1> outputs(const PeriodicGait<T>& g) {
  Eigen::Matrix<T, Eigen::Dynamic, 1> y(8 + g.inequalities.size());
  y << g.objective, g.f_mech, g.f_usq, g.speed_equality, g.step_length, g.step_period, g.mean_speed, g.floquet,
      g.inequalities;
  return y;
}

Eigen::MatrixXd ad_jacobian(const GaitDerivatives& d) {
  Eigen::MatrixXd J(8 + d.inequalities.rows(), d.objective.size());
  J << d.objective, d.f_mech, d.f_usq, d.speed_equality, d.step_length, d.step_period, d.mean_speed, d.floquet,
      d.inequalities;
  return J;
}

struct Agreement {
  double worst = 0.0;  // max relative error over entries with |complex step| >= 1e-6
  int entries = 0;
};

void compare_column(const Eigen::VectorXcd& y, const Eigen::VectorXd& ad, Agreement& a) {
  for (int r = 0; r < y.size(); ++r) {
    const double cs = y(r).imag() / kStep;
    if (std::abs(cs) < 1e-6) continue;
    a.worst = std::max(a.worst, std::abs(ad(r) - cs) / std::abs(cs));
    ++a.entries;
  }
}

TEST(GaitDerivatives, GaitParameterJacobianMatchesComplexStepOnRandomFeasibleGaits) {
  std::mt19937_64 rng(2018);
  int gaits = 0;
  Agreement total;
  for (const char* foot : kReferenceFeet) {
    const auto& ref = testing::reference_gait(foot);
    ASSERT_TRUE(ref.start.feasible) << foot << ": " << ref.start.message;
    const GaitEvaluator& ev = *ref.evaluator;
    const WalkerModel<C> mc = cast_model<C>(ev.model());
    const GaitOptions opt{Objective::mechanical, 1.3, false};
    int kept = 0, draws = 0;
    Agreement a;
    while (kept < 35 && draws < 2000) {
      ++draws;
      const Eigen::VectorXd x = perturbed_gait(ev, ref.start.x, 0.01, rng);
      const GaitEvaluation e = ev.evaluate_with_derivatives(x, opt);
      if (!e.gait.real || e.gait.inequalities.maxCoeff() > 0.0) continue;  // feasible gaits only
      ++kept;
      const Eigen::MatrixXd J = ad_jacobian(e.derivatives);
      for (int j = 0; j < x.size(); ++j) {
        Eigen::VectorXcd xc = x.cast<C>();
        xc(j) += C(0.0, kStep);
        const PeriodicGait<C> g = periodic_gait(mc, ev.basis(), xc, opt);
        ASSERT_TRUE(g.real) << foot << " direction " << j;
        compare_column(outputs(g), J.col(j), a);
      }
    }
    std::printf("%s: %d feasible gaits (%d draws), %d Jacobian entries >= 1e-6, max relative error %.2e\n", foot, kept,
                draws, a.entries, a.worst);
    EXPECT_EQ(kept, 35) << foot;
    gaits += kept;
    total.worst = std::max(total.worst, a.worst);
    total.entries += a.entries;
  }
  EXPECT_GE(gaits, 100);
  EXPECT_LE(total.worst, 1e-7);
}

TEST(GaitDerivatives, ModelParameterDerivativesMatchComplexStep) {
  for (const char* foot : kReferenceFeet) {
    const auto& ref = testing::reference_gait(foot);
    const GaitEvaluator& ev = *ref.evaluator;
    const WalkerModel<double>& m = ev.model();
    const GaitOptions opt{Objective::squared_torque, 1.3, false};
    const int np = model_parameter_count(m), nx = ev.parameter_count();
    std::vector<int> all(np);
    for (int i = 0; i < np; ++i) all[i] = i;
    const GaitEvaluation e = ev.evaluate_with_derivatives(ref.start.x, opt, all);
    ASSERT_TRUE(e.has_derivatives);
    const Eigen::MatrixXd J = ad_jacobian(e.derivatives);
    ASSERT_EQ(J.cols(), nx + np);
    const Eigen::VectorXd p = model_parameters(m);
    Agreement a;
    for (int i = 0; i < np; ++i) {
      Eigen::VectorXcd pc = p.cast<C>();
      pc(i) += C(0.0, kStep);
      const PeriodicGait<C> g = periodic_gait(with_model_parameters<C>(m, pc), ev.basis(), ref.start.x.cast<C>().eval(), opt);
      ASSERT_TRUE(g.real);
      compare_column(outputs(g), J.col(nx + i), a);
    }
    const auto names = model_parameter_names(m);
    std::printf("%s: %d model parameters (%s ... %s), %d entries >= 1e-6, max relative error %.2e\n", foot, np,
                names.front().c_str(), names.back().c_str(), a.entries, a.worst);
    EXPECT_LE(a.worst, 1e-7) << foot;
    EXPECT_GT(a.entries, 100) << foot;
  }
}

TEST(GaitDerivatives, ModelParameterNamesAreValidatedWithTheKnownList) {
  const WalkerModel<double> m = testing::reference_model("P1-barefoot-left-HM");
  EXPECT_EQ(model_parameter_index(m, "k_HM"), segment_parameter_count + 4);
  try {
    model_parameter_index(m, "l_MT");  // an HMT parameter, not in an HM scene
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& err) {
    EXPECT_NE(std::string(err.what()).find("l_MT"), std::string::npos);
    EXPECT_NE(std::string(err.what()).find("theta_F0"), std::string::npos);
  }
}

}  // namespace
}  // namespace cyclopt::walker
