#pragma once
// The seed's method end to end (seed 000, ch. 4.3): the multistage loop around Nelder-Mead.
//   1. From the start vector build a simplex with edge lambda and minimise; while the result
//      differs from the start vector, restart from it.
//   2. When it no longer moves (or the stage budget is spent), halve lambda and go to 1, until
//      lambda < min_step.
//   3. Then double the support points (4 -> 8 -> 16 -> 32, same function), reset lambda, go to 1.
// Every evaluation integrates the model once (swing_simulation.hpp) and scores it (eq. 4.9, 4.10,
// 4.14).

#include "cyclopt/giant_swing/task_spec.hpp"

#include <vector>

namespace cyclopt::giant_swing {

// Scores one hip-torque profile for a task; counts the model integration.
struct TaskEvaluation {
  double score = 0.0;
  SimulationResult simulation;
};
TaskEvaluation evaluate_task(const Model& model, const TaskSpec& spec, const HipTorqueProfile& torque);

struct StageReport {
  int support_points = 0;
  double step = 0.0;      // lambda, Nm
  double score = 0.0;     // best score after this stage
  int evaluations = 0;    // model integrations in this stage
};

struct SeedMethodResult {
  HipTorqueProfile torque;
  TaskEvaluation best;
  int integrations = 0;  // model integrations in total
  double wall_seconds = 0.0;
  bool budget_exhausted = false;
  std::vector<StageReport> stages;
};

SeedMethodResult optimise_seed_method(const Model& model, const TaskSpec& spec);

}  // namespace cyclopt::giant_swing
