// What a walker job stores of a continuation's points (jobs/walker/walker_points.hpp CurveStore):
// every point the corrector ended, converged or not, with its curve; but not a point whose solve
// the job itself stopped (cancel, shutdown): a resumed attempt computes only the points not
// stored, so a stored stopped solve would stand for the point for good.
#include "cyclopt/jobs/walker/walker_points.hpp"

#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/studies/walker_family.hpp"
#include "cyclopt/walker/gait_problem.hpp"
#include "cyclopt/walker/starting_gait.hpp"
#include "memory_job.hpp"

#include <gtest/gtest.h>

namespace cyclopt::service {
namespace {

// The automatic starting gait at 1 m/s as a point whose corrector ended with `termination`.
continuation::CurvePoint point_ended_by(nlp::Termination termination, const walker::WalkerModel<double>& model,
                                       const walker::GaitProblemOptions& problem) {
  walker::StartingGaitOptions so;
  so.speed = problem.speed;
  continuation::CurvePoint c;
  c.parameter = problem.speed;
  c.x = walker::GaitProblem(model, problem).initial_point(walker::starting_gait(walker::GaitEvaluator(model), so).x);
  c.corrector.termination = termination;
  c.converged = termination == nlp::Termination::converged;
  return c;
}

TEST(CurveStore, KeepsEveryEndedSolveButNotOneTheJobStopped) {
  const walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset("point").spec);
  const walker::GaitProblemOptions problem{walker::Objective::mechanical, 1.0, walker::Quadrature::trapezoid, {}};
  const continuation::ParametricProblem family = studies::walker_family(model, problem, "speed");
  MemoryJob job;
  jobs::CurveStore store(job, family, 0, true);
  EXPECT_TRUE(store(point_ended_by(nlp::Termination::converged, model, problem)));
  EXPECT_TRUE(store(point_ended_by(nlp::Termination::max_iterations, model, problem)));
  EXPECT_EQ(job.points.size(), 2u);

  job.stop = StopReason::cancelled;
  EXPECT_FALSE(store(point_ended_by(nlp::Termination::user_stop, model, problem)));
  EXPECT_EQ(job.points.size(), 2u) << "the stopped solve was stored";
}

}  // namespace
}  // namespace cyclopt::service
