// The evaluator's Jacobian (one Dual<n_x> pass on the double model, grid points differentiated
// locally and chained, grid_point.hpp) against the plain reference path (chunks of Dual<8>, whole
// model cast to Dual) on random feasible gaits of every reference foot, for both objectives and
// quadrature rules, and with free model parameters (chunked path, double model for x-only chunks).
#include "reference_gaits.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

namespace cyclopt::walker {
namespace {

using testing::kReferenceFeet;

// Largest |J_a - J_b| of a row relative to the row's largest |J_b|, over all rows.
double row_relative_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  double worst = 0.0;
  for (int r = 0; r < a.rows(); ++r) {
    const double scale = b.row(r).cwiseAbs().maxCoeff();
    if (scale > 0.0) worst = std::max(worst, (a.row(r) - b.row(r)).cwiseAbs().maxCoeff() / scale);
  }
  return worst;
}

double compare(const GaitEvaluator& ev, const Eigen::VectorXd& x, const GaitOptions& opt, const std::vector<int>& params) {
  const GaitEvaluation fast = ev.evaluate_with_derivatives(x, opt, params);
  const GaitEvaluation ref = ev.evaluate_with_reference_derivatives(x, opt, params);
  EXPECT_TRUE(fast.has_derivatives && ref.has_derivatives);
  EXPECT_EQ(fast.gait.objective, ref.gait.objective);  // the value pass is the same
  const Eigen::MatrixXd Jf = fast.derivatives.stacked(), Jr = ref.derivatives.stacked();
  EXPECT_EQ(Jf.cols(), ev.parameter_count() + static_cast<int>(params.size()));
  EXPECT_TRUE(Jf.allFinite());
  return row_relative_difference(Jf, Jr);
}

TEST(GaitJacobianPaths, FastJacobianEqualsReferenceOnRandomFeasibleGaits) {
  std::mt19937_64 rng(4711);
  const GaitOptions options[] = {{Objective::mechanical, 1.3, false, Quadrature::trapezoid},
                                 {Objective::squared_torque, 1.1, false, Quadrature::corrected_trapezoid}};
  for (const char* foot : kReferenceFeet) {
    const auto& ref = testing::reference_gait(foot);
    ASSERT_TRUE(ref.start.feasible) << foot << ": " << ref.start.message;
    const GaitEvaluator& ev = *ref.evaluator;
    int kept = 0, draws = 0;
    double worst = 0.0;
    while (kept < 12 && draws < 2000) {
      ++draws;
      const Eigen::VectorXd x = perturbed_gait(ev, ref.start.x, 0.01, rng);
      const GaitOptions& opt = options[kept % 2];
      const PeriodicGait<double> g = ev.evaluate(x, opt);
      if (!g.real || g.inequalities.maxCoeff() > 0.0) continue;  // feasible gaits only
      ++kept;
      worst = std::max(worst, compare(ev, x, opt, {}));
    }
    std::printf("%s: %d feasible gaits (%d draws), max row-relative Jacobian difference %.2e\n", foot, kept, draws, worst);
    EXPECT_EQ(kept, 12) << foot;
    EXPECT_LE(worst, 1e-10) << foot;
  }
}

TEST(GaitJacobianPaths, FreeModelParametersGiveTheReferenceJacobian) {
  for (const char* foot : kReferenceFeet) {
    const auto& ref = testing::reference_gait(foot);
    const GaitEvaluator& ev = *ref.evaluator;
    const int np = model_parameter_count(ev.model());
    const std::vector<int> params = {0, 3, np - 1};  // l_T, a mass parameter, the last (theta_F0 or J_F)
    const double worst = compare(ev, ref.start.x, GaitOptions{Objective::mechanical, 1.3, false}, params);
    std::printf("%s: x and %d model parameters, max row-relative Jacobian difference %.2e\n", foot,
                static_cast<int>(params.size()), worst);
    EXPECT_LE(worst, 1e-10) << foot;
  }
}

}  // namespace
}  // namespace cyclopt::walker
