// Held joints (walker/held_joints.hpp): which joints a gait holds still, the equalities that tie a
// joint's Bezier coefficients (their Jacobian against the complex step of the virtual constraints
// 5.55-5.62), f_mech without the held joints' powers, and the checks that name their field.
#include "cyclopt/walker/held_joint_solve.hpp"
#include "cyclopt/walker/held_joints.hpp"
#include "cyclopt/walker/positive_power.hpp"
#include "cyclopt/walker/virtual_constraints.hpp"

#include "reference_gaits.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <stdexcept>
#include <string>

namespace cyclopt::walker {
namespace {

using C = std::complex<double>;
constexpr double kStep = 1e-30;

// The reference foot's starting gait at 1.3 m/s (reference_gaits.hpp, computed once per binary); with
// no free parameters z is the gait parameters themselves.
struct Fixture {
  const testing::ReferenceGait& reference = testing::reference_gait("P2-shoes-left-HMT");
  const WalkerModel<double>& model = reference.evaluator->model();
  GaitProblemOptions options;
  Eigen::VectorXd z = reference.start.x;
};

std::string field_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return std::string(e.what()).substr(0, std::string(e.what()).find(':'));
  }
  return "";
}

TEST(HeldJoints, FindsTheJointsStillOverTheWholeStep) {
  PeriodicGait<double> g;
  g.real = true;
  g.trajectory.q_dot.setZero(7, 5);  // theta, then six joints
  g.trajectory.q_dot.row(0).setConstant(1.0);
  for (int j = 1; j < 7; ++j) g.trajectory.q_dot.row(j).setLinSpaced(-2.0, 2.0);
  g.trajectory.q_dot.row(3) *= 1e-5;  // K1: 2e-5 rad/s at most
  g.trajectory.q_dot.row(5).setZero();  // A1: still but for 1e-4 rad/s at one point
  g.trajectory.q_dot(5, 2) = 1e-4;
  EXPECT_EQ(held_joints(g, 1e-3), (std::vector<int>{2, 4}));
  EXPECT_EQ(held_joints(g, 1e-5), (std::vector<int>{2}));
  g.real = false;
  EXPECT_TRUE(held_joints(g, 1e-3).empty());
  EXPECT_EQ(field_of([&] { (void)held_joints(g, 1.0); }), "still_ratio");
}

TEST(HeldJoints, TiedCoefficientsAndTheirJacobianMatchTheComplexStep) {
  const Fixture f;
  HeldJointProblem problem(f.model, f.options, {joint_K1, joint_A1});
  const int M = f.model.constants.bezier_degree;
  ASSERT_EQ(problem.num_equalities(), 1 + 2 * M);
  nlp::Evaluation e, plain;
  ASSERT_TRUE(problem.evaluate(f.z, true, e).ok);
  ASSERT_TRUE(GaitProblem(f.model, f.options).evaluate(f.z, true, plain).ok);
  EXPECT_EQ(e.equalities(0), plain.equalities(0));
  EXPECT_TRUE(e.inequalities == plain.inequalities);
  const WalkerModel<C> mc = cast_model<C>(f.model);
  double worst = 0.0;
  for (int k = 0; k < f.z.size(); ++k) {
    Eigen::VectorXcd xc = f.z.cast<C>();
    xc(k) += C(0.0, kStep);
    const VirtualConstraints<C> vc = virtual_constraints(mc, xc);
    ASSERT_TRUE(vc.ok);
    int row = 1;
    for (int j : {joint_K1, joint_A1})
      for (int i = 0; i < M; ++i, ++row) {
        const C difference = vc.alpha(j, i + 1) - vc.alpha(j, i);
        EXPECT_NEAR(e.equalities(row), difference.real(), 1e-13);
        worst = std::max(worst, std::abs(e.equality_jacobian(row, k) - difference.imag() / kStep));
      }
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_EQ(problem.constraint_name(true, 1 + M), "held joint A1: alpha_1 - alpha_0");
}

TEST(HeldJoints, FMechLeavesOutTheHeldJointsPowers) {
  const Fixture f;
  GaitProblem plain(f.model, f.options);
  HeldJointProblem held(f.model, f.options, {joint_A1});
  const PeriodicGait<double> g = plain.gait_at(f.z);
  // The left-out joint's energy per step by the seed's rule, over m g L as f_mech (5.102).
  double energy = 0.0;
  for (Eigen::Index i = 0; i + 1 < g.joint_power.cols(); ++i)
    energy += positive_part_trapezoid(g.joint_power(joint_A1, i), g.joint_power(joint_A1, i + 1), g.interval_duration(i));
  ASSERT_GT(energy, 0.0);
  const double weight = f.model.total_mass * f.model.constants.gravity * g.step_length;
  nlp::Evaluation e, p, values;
  ASSERT_TRUE(held.evaluate(f.z, true, e).ok);
  ASSERT_TRUE(held.evaluate(f.z, false, values).ok);
  ASSERT_TRUE(plain.evaluate(f.z, true, p).ok);
  EXPECT_NEAR(e.objective, g.f_mech - energy / weight, 1e-15);
  EXPECT_EQ(values.objective, e.objective);
  // The gradient loses the joint's kinked terms (their slopes along the powers' gradients) and keeps
  // the others'; the solver sees no kink of the held joint.
  Eigen::VectorXd expected = p.gradient;
  const Eigen::Index points = g.joint_power.cols();
  std::size_t held_terms = 0;
  for (const nlp::KinkedTerm& t : p.kinks.terms)
    if (t.sample / points == joint_A1) {
      expected -= t.slope * p.kinks.jacobian.row(t.sample).transpose();
      ++held_terms;
    }
  EXPECT_EQ(held_terms, static_cast<std::size_t>(2 * (points - 1)));
  EXPECT_LT((e.gradient - expected).lpNorm<Eigen::Infinity>(), 1e-15);
  EXPECT_EQ(e.kinks.terms.size(), p.kinks.terms.size() - held_terms);
  for (const nlp::KinkedTerm& t : e.kinks.terms) EXPECT_NE(t.sample / points, joint_A1);
}

TEST(HeldJoints, NamesTheFieldOutOfRange) {
  const Fixture f;
  GaitProblemOptions free = f.options;
  free.free_parameters = {"l_HM"};
  EXPECT_EQ(field_of([&] { HeldJointProblem(f.model, free, {joint_A1}); }), "free_parameters");
  GaitProblemOptions banded = f.options;
  banded.positive_power_band = 0.1;
  EXPECT_EQ(field_of([&] { HeldJointProblem(f.model, banded, {joint_A1}); }), "objective");
  EXPECT_EQ(field_of([&] { HeldJointProblem(f.model, f.options, {6}); }), "joints");
  HeldJointSolveOptions h;
  h.still_ratio = 0.0;
  EXPECT_EQ(field_of([&] { (void)solve_on_held_joints(f.model, f.options, nlp::seed_table_6_2_options(), {}, h); }), "still_ratio");
}

TEST(HeldJoints, AConvergedRunIsLeftAsItIs) {
  const Fixture f;
  nlp::SolverSummary start;
  start.termination = nlp::Termination::converged;
  start.x = f.z;
  start.objective = 0.5;
  const HeldJointSolve s = solve_on_held_joints(f.model, f.options, nlp::seed_table_6_2_options(), start);
  EXPECT_TRUE(s.joints.empty());
  EXPECT_FALSE(s.manifold.has_value());
  EXPECT_EQ(s.result.objective, 0.5);
}

}  // namespace
}  // namespace cyclopt::walker
