// The smoothing homotopy's schedule and its checks (walker/smoothing_homotopy.hpp): stages e =
// first, first * factor, ... >= last, each starting where the one before ended, then the exact
// f_mech's polish; options out of range name their field.
#include "cyclopt/nlp/solver_options.hpp"
#include "cyclopt/walker/smoothing_homotopy.hpp"

#include "reference_gaits.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace cyclopt::walker {
namespace {

// The reference foot's starting gait at 1.3 m/s (reference_gaits.hpp, computed once per binary); with
// no free parameters z is the gait parameters themselves.
struct Fixture {
  const testing::ReferenceGait& reference = testing::reference_gait("point");
  const WalkerModel<double>& model = reference.evaluator->model();
  GaitProblemOptions options;
  Eigen::VectorXd z0 = reference.start.x;
};

TEST(SmoothingHomotopy, SolvesEachStageFromTheLastAndPolishesTheExactObjective) {
  const Fixture f;
  nlp::SolverOptions solver = nlp::seed_table_6_2_options();
  solver.max_iterations = 2;  // the schedule, not the optima
  const SmoothingHomotopySummary s = solve_by_smoothing(f.model, f.options, solver, f.z0, {});
  ASSERT_EQ(s.smoothing.size(), 3u);
  EXPECT_DOUBLE_EQ(s.smoothing[0], 1.0);
  EXPECT_DOUBLE_EQ(s.smoothing[1], 0.1);
  EXPECT_NEAR(s.smoothing[2], 0.01, 1e-15);
  ASSERT_EQ(s.stages.size(), 3u);
  ASSERT_TRUE(s.polish.has_value());
  EXPECT_EQ(&s.final(), &*s.polish);
  // The polish's objective is the exact f_mech at its point, below each smoothed stage's (s > max(p, 0)).
  GaitProblem exact(f.model, f.options);
  nlp::Evaluation e;
  ASSERT_TRUE(exact.evaluate(s.polish->x, false, e).ok);
  EXPECT_DOUBLE_EQ(e.objective, s.polish->objective);
  ASSERT_TRUE(exact.evaluate(s.stages.back().x, false, e).ok);
  EXPECT_LT(e.objective, s.stages.back().objective);
}

TEST(SmoothingHomotopy, NamesTheFieldOutOfRange) {
  const Fixture f;
  const nlp::SolverOptions solver = nlp::seed_table_6_2_options();
  const auto field_of = [&](SmoothingHomotopyOptions h, GaitProblemOptions po) -> std::string {
    try {
      (void)solve_by_smoothing(f.model, po, solver, f.z0, h);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what()).substr(0, std::string(e.what()).find(':'));
    }
    return "";
  };
  SmoothingHomotopyOptions h;
  h.first = 0.0;
  EXPECT_EQ(field_of(h, f.options), "first");
  h = {};
  h.last = 2.0;
  EXPECT_EQ(field_of(h, f.options), "last");
  h = {};
  h.factor = 1.0;
  EXPECT_EQ(field_of(h, f.options), "factor");
  GaitProblemOptions banded = f.options;
  banded.positive_power_band = 1e-3;
  EXPECT_EQ(field_of({}, banded), "options");
}

}  // namespace
}  // namespace cyclopt::walker
