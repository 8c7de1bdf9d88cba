// Ipopt on the walker gait NLP (point feet, P = 50, f_usq), against the SQP's optimum: the
// regression guard for the adapter's walker settings (damped-BFGS Hessian, adaptive mu; see
// bench/results/walker_solvers.txt: with Ipopt's L-BFGS or monotone mu from 0.1 it does not
// converge), and for the warm start used by the continuation's Ipopt corrector (multipliers and
// the difference Hessian at the start), and for the distant-start settings with which Ipopt
// reaches a KKT point from the automatic starting gait on a rolling foot.
#include "reference_gaits.hpp"

#include "cyclopt/walker/distant_start_solver.hpp"
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

// From the automatic starting gait on HM feet (f_mech, 1.3 m/s), Ipopt's damped BFGS alone stops
// at max_iterations (here, P = 100: 600 iterations, KKT error 4e-2; P = 200: walker_solvers.txt);
// with the refreshed difference Hessian of distant_start_solver it converges (430 iterations).
TEST(GaitIpopt, ReachesAKktPointFromTheStartingGaitOnAnHmFoot) {
  const WalkerModel<double> model = testing::reference_model("P1-barefoot-left-HM", 100);
  const GaitProblemOptions problem{Objective::mechanical, 1.3, Quadrature::trapezoid, {}};
  nlp::SolverOptions o = ipopt_options();
  o.max_iterations = 600;
  const GaitOptimum ipopt = optimise_gait(model, problem, distant_start_solver(o));
  const nlp::SolverSummary& s = ipopt.summary;
  ASSERT_EQ(s.termination, nlp::Termination::converged) << s.message << " after " << s.iterations << " iterations";
  EXPECT_LE(s.kkt_error, 1e-5);
  EXPECT_LE(s.constraint_violation, 1e-8);
  EXPECT_LT(s.objective, 0.1 * ipopt.start_objective);  // a walking optimum, not a stationary start
}

}  // namespace
}  // namespace cyclopt::walker
