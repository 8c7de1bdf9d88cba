// Ipopt on the walker gait NLP (point feet, P = 50, f_usq), against the SQP's optimum: the
// regression guard for the adapter's walker settings (damped-BFGS Hessian, adaptive mu; see
// bench/results/walker_solvers.txt: with Ipopt's L-BFGS or monotone mu from 0.1 it does not
// converge), and for the warm start used by the continuation's Ipopt corrector (multipliers and
// the difference Hessian at the start).
#include "reference_gaits.hpp"

#include "cyclopt/walker/gait_optimisation.hpp"

#include <gtest/gtest.h>

namespace cyclopt::walker {
namespace {

constexpr int kPoints = 50;
constexpr double kSpeed = 1.0;

GaitProblemOptions problem_options(double speed) { return {Objective::squared_torque, speed, Quadrature::trapezoid, {}}; }

nlp::SolverOptions ipopt_options() {
  nlp::SolverOptions o = nlp::seed_table_6_2_options();
  o.solver = nlp::SolverKind::ipopt;
  o.max_iterations = 200;
  return o;
}

// The SQP optimum at kSpeed from the automatic starting gait, computed once.
const GaitOptimum& sqp_optimum() {
  static const GaitOptimum optimum =
      optimise_gait(testing::reference_model("point", kPoints), problem_options(kSpeed), nlp::seed_table_6_2_options());
  return optimum;
}

TEST(GaitIpopt, ConvergesToTheSqpOptimumFromAPerturbedStart) {
  const GaitOptimum& sqp = sqp_optimum();
  ASSERT_TRUE(sqp.summary.success()) << sqp.summary.message;
  Eigen::VectorXd start = sqp.z;
  for (Eigen::Index i = 0; i < start.size(); ++i) start(i) += (i % 2 ? 0.02 : -0.02);  // deterministic, evaluable
  const GaitOptimum ipopt = optimise_gait(sqp.model, problem_options(kSpeed), ipopt_options(), start);
  const nlp::SolverSummary& s = ipopt.summary;
  ASSERT_EQ(s.termination, nlp::Termination::converged) << s.message << " after " << s.iterations << " iterations";
  EXPECT_LE(s.iterations, 150);  // 116 measured
  EXPECT_LE(s.kkt_error, 1e-5);
  EXPECT_NEAR(s.objective, sqp.summary.objective, 1e-6 * sqp.summary.objective);
}

TEST(GaitIpopt, WarmStartFromTheNeighbouringOptimumNeedsFewIterations) {
  const GaitOptimum& sqp = sqp_optimum();
  ASSERT_TRUE(sqp.summary.success()) << sqp.summary.message;
  nlp::SolverOptions o = ipopt_options();
  o.ipopt.warm_start = nlp::IpoptWarmStart{sqp.summary.equality_multipliers, sqp.summary.inequality_multipliers,
                                           sqp.summary.bound_multipliers};
  o.ipopt.difference_hessian_start = true;
  const GaitOptimum warm = optimise_gait(sqp.model, problem_options(kSpeed + 0.05), o, sqp.z);
  ASSERT_EQ(warm.summary.termination, nlp::Termination::converged) << warm.summary.message;
  EXPECT_LE(warm.summary.iterations, 15);
  EXPECT_LE(warm.summary.kkt_error, 1e-5);
}

}  // namespace
}  // namespace cyclopt::walker
