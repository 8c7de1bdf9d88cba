#include "cyclopt/giant_swing/seed_optimiser.hpp"

#include "cyclopt/nlp/nelder_mead.hpp"

#include <chrono>

namespace cyclopt::giant_swing {

TaskEvaluation evaluate_task(const Model& model, const TaskSpec& spec, const HipTorqueProfile& torque) {
  TaskEvaluation e;
  e.simulation = simulate_swings(model, PiecewiseLinearTorque(torque), initial_state(spec), spec.rounds, simulation_options(spec));
  e.score = evaluation_score(spec.weights, e.simulation, spec.rounds, spec.omega);
  return e;
}

SeedMethodResult optimise_seed_method(const Model& model, const TaskSpec& spec) {
  const auto start = std::chrono::steady_clock::now();
  const OptimiserSettings& o = spec.optimiser;
  SeedMethodResult result;
  result.torque.support_values =
      o.start_vector ? *o.start_vector : Eigen::VectorXd::Zero(Eigen::Index(o.support_points));
  auto score_of = [&](const Eigen::VectorXd& z) {
    ++result.integrations;
    return evaluate_task(model, spec, HipTorqueProfile{z}).score;
  };
  double best = score_of(result.torque.support_values);
  for (;;) {
    for (double step = o.initial_step; step >= o.min_step; step *= 0.5) {
      StageReport stage{int(result.torque.support_values.size()), step, best, 0};
      for (;;) {  // step 1: restart from the result until it stops moving
        nlp::NelderMeadOptions nm;
        nm.initial_step = step;
        nm.f_tolerance = o.f_tolerance;
        nm.max_evaluations = std::min(o.max_evaluations_per_run, o.max_evaluations - result.integrations);
        if (nm.max_evaluations <= int(result.torque.support_values.size()) + 1) {
          result.budget_exhausted = true;
          break;
        }
        const nlp::NelderMeadSummary s = nlp::nelder_mead(score_of, result.torque.support_values, nm);
        stage.evaluations += s.evaluations;
        const double change = (s.x - result.torque.support_values).lpNorm<Eigen::Infinity>();
        const bool moved = change > o.same_vector_tolerance * std::max(1.0, s.x.lpNorm<Eigen::Infinity>());
        if (s.f < best) {
          best = s.f;
          result.torque.support_values = s.x;
        }
        if (!moved || stage.evaluations >= o.max_evaluations_per_stage) break;
      }
      stage.score = best;
      result.stages.push_back(stage);
      if (result.budget_exhausted) break;
    }
    if (result.budget_exhausted || 2 * result.torque.support_values.size() > o.max_support_points) break;
    result.torque = refined(result.torque);  // step 3
    best = score_of(result.torque.support_values);  // same function, but rounding can flip an event race
  }
  result.best = evaluate_task(model, spec, result.torque);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace cyclopt::giant_swing
