// The evaluator's Jacobian (one Dual<n_x> pass on the double model, grid points differentiated
// locally and chained, grid_point.hpp) against the plain reference path (chunks of Dual<8>, whole
// model cast to Dual) on random feasible gaits of every reference foot, for both objectives and
// quadrature rules, and with free model parameters (chunked path, double model for x-only chunks).
// On a spare core the chunked passes and the difference Hessian's columns are split between two
// threads: bitwise the same Jacobian and Hessian (nlp/spare_core.hpp).
#include "reference_gaits.hpp"

#include "cyclopt/nlp/cached_evaluator.hpp"
#include "cyclopt/nlp/difference_hessian.hpp"
#include "cyclopt/nlp/spare_core.hpp"
#include "cyclopt/walker/gait_problem.hpp"

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

// The Jacobian and the difference Hessian of a GaitProblem with every evaluation in one thread and
// with the work split between two (nlp::SpareCoreRule::always).
struct SplitResults {
  Eigen::MatrixXd jacobian, hessian;
  int jacobian_evaluations = 0;
};

SplitResults derivatives_with(nlp::SpareCoreRule rule, const WalkerModel<double>& model, const Eigen::VectorXd& z,
                              const std::vector<std::string>& free) {
  nlp::set_spare_core_rule(rule);
  GaitProblem problem(model, {Objective::mechanical, 1.3, Quadrature::trapezoid, free});
  nlp::SolverSummary counts;
  nlp::CachedEvaluator evaluator(problem, counts);
  EXPECT_TRUE(evaluator.evaluate(z, true).ok);
  const nlp::Evaluation at = evaluator.evaluation();
  SplitResults r;
  r.jacobian.resize(1 + at.inequalities.size(), z.size());
  r.jacobian << at.equality_jacobian, at.inequality_jacobian;
  const Eigen::VectorXd y_eq = Eigen::VectorXd::Constant(1, 0.3);
  const Eigen::VectorXd y_in = Eigen::VectorXd::LinSpaced(at.inequalities.size(), 0.0, 1.0);
  const std::optional<Eigen::MatrixXd> H = nlp::lagrangian_hessian_by_differences(evaluator, z, at, y_eq, y_in);
  EXPECT_TRUE(H.has_value());
  if (H) r.hessian = *H;
  r.jacobian_evaluations = counts.jacobian_evaluations;
  nlp::set_spare_core_rule(nlp::SpareCoreRule::measured);
  return r;
}

TEST(GaitJacobianPaths, PassesSplitOverTwoThreadsGiveBitwiseTheSameDerivatives) {
  for (const char* foot : kReferenceFeet) {
    const auto& ref = testing::reference_gait(foot);
    const GaitEvaluator& ev = *ref.evaluator;
    // x only (one pass; the Hessian's columns shared out) and with two free foot parameters where
    // the foot has them (chunks of Dual<8> shared out too).
    std::vector<std::vector<std::string>> frees{{}};
    if (std::string(foot) != "point") frees.push_back({"h_F", "k_HM"});
    for (const auto& free : frees) {
      Eigen::VectorXd z = ref.start.x;
      if (!free.empty()) z = GaitProblem(ev.model(), {Objective::mechanical, 1.3, Quadrature::trapezoid, free}).initial_point(ref.start.x);
      const SplitResults one = derivatives_with(nlp::SpareCoreRule::never, ev.model(), z, free);
      const SplitResults two = derivatives_with(nlp::SpareCoreRule::always, ev.model(), z, free);
      EXPECT_TRUE(one.jacobian == two.jacobian) << foot << " with " << free.size() << " free parameters: max difference "
                                                << (one.jacobian - two.jacobian).cwiseAbs().maxCoeff();
      EXPECT_TRUE(one.hessian == two.hessian) << foot << " with " << free.size() << " free parameters";
      EXPECT_EQ(one.jacobian_evaluations, two.jacobian_evaluations) << foot;  // the helper's count too
      EXPECT_EQ(one.jacobian_evaluations, 1 + z.size()) << foot;
    }
  }
}

}  // namespace
}  // namespace cyclopt::walker
