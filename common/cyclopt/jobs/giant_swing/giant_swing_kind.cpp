#include "cyclopt/jobs/giant_swing/giant_swing_kind.hpp"

#include "cyclopt/giant_swing/one_step_map.hpp"
#include "cyclopt/giant_swing/seed_optimiser.hpp"
#include "cyclopt/io/seed_method_json.hpp"
#include "cyclopt/io/task_spec_json.hpp"
#include "cyclopt/jobs/giant_swing/giant_swing_job_spec.hpp"
#include "cyclopt/jobs/solver_progress.hpp"

#include <stdexcept>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

using namespace giant_swing;

void add_rounds(const SimulationResult& sim, double omega, nlohmann::json& values) {
  nlohmann::json rounds = nlohmann::json::array();
  for (const RoundResult& r : sim.rounds) rounds.push_back(io::to_json(r, omega));
  values["rounds"] = rounds;
  values["rounds_completed"] = sim.rounds.size();
  if (sim.failed) {
    values["failure_reason"] = sim.failure_reason;
    values["failure_phi_deg"] = sim.failure_phi * kDegPerRad;
  }
}

storage::SolutionPoint seed_point(const Model& model, const GiantSwingJob& job, JobContext& ctx) {
  ctx.report_progress({.curve_id = 0, .points_total = 1, .message = "seed method, " + job.motion});
  const SeedMethodResult r = optimise_seed_method(model, job.task);
  ctx.count_iterations(r.integrations);
  storage::SolutionPoint p;
  p.values = io::to_json(r, job.task);
  add_rounds(r.best.simulation, job.task.omega, p.values);
  p.values["integrations"] = r.integrations;
  p.objective = r.best.score;
  p.iterations = r.integrations;
  p.status = r.best.simulation.failed && r.best.simulation.rounds.empty() ? "failed" : "ok";
  return p;
}

storage::SolutionPoint bezier_point(const Model& model, const GiantSwingJob& job, JobContext& ctx) {
  MinimumJerkSettings settings = job.bezier;
  settings.solver.on_iteration =
      solver_progress(ctx, {.curve_id = 0, .points_total = 1, .message = "bezier minimum jerk, " + job.motion});
  settings.solver.should_stop = stop_predicate(ctx);
  // periodic: the closed swing from and to omega, repeated (its start rate is omega).
  const MinimumJerkResult r = solve_minimum_jerk(model, job.task, settings);
  if (r.coefficients.size() == 0) throw std::runtime_error("giant swing (bezier): " + r.message);
  storage::SolutionPoint p;
  p.values["task"] = io::to_json(job.task);
  p.values["coefficients_rad"] = std::vector<double>(r.coefficients.begin(), r.coefficients.end());
  p.values["free_coefficients"] = r.coefficients.size();
  p.values["reduced_model"] = {{"jerk_rad2_s5", r.jerk},
                               {"start_jerk_rad2_s5", r.start_jerk},
                               {"phi_rate_over_omega_minus_1", r.boundary_error},
                               {"friction_loss_J", r.friction_loss},
                               {"moment_Nm2_s", r.torque_integral}};
  p.values["solver"] = {{"solver", nlp::to_string(settings.solver.solver)},
                        {"termination", nlp::to_string(r.summary.termination)},
                        {"success", r.summary.success()},
                        {"iterations", r.summary.iterations},
                        {"message", r.message}};
  p.values["integrations"] = r.integrations;
  p.values["wall_seconds"] = r.wall_seconds;
  // The motion in the full model under the constraint-enforcing hip torque.
  const VirtualConstraintTorque law(bezier_from_free(r.coefficients), kConstraintGainP, kConstraintGainD, model);
  SimulationOptions o = simulation_options(job.task);
  o.integrator.relative_tolerance = 1e-12;
  o.integrator.absolute_tolerance = 1e-14;
  add_rounds(simulate_swings(model, law, initial_state(job.task), job.task.rounds, o), job.task.omega, p.values);
  if (job.task.kind == TaskKind::periodic_sequence) {
    const OneStepJacobian J = one_step_jacobian(model, law, SectionState(job.task.omega, 0.0, 0.0), o);
    if (J.ok) {
      std::vector<double> moduli;
      for (const auto& lambda : floquet_multipliers(J.jacobian)) moduli.push_back(std::abs(lambda));
      p.values["floquet_multiplier_moduli"] = moduli;
    }
  }
  p.objective = r.jerk;
  p.constraint_violation = std::abs(r.boundary_error);
  p.iterations = r.summary.iterations;
  p.status = r.ok ? nlp::to_string(r.summary.termination) : "failed: " + r.message;
  return p;
}

void run_giant_swing(const GiantSwingJob& job, JobContext& ctx) {
  ctx.announce(1);
  ctx.add_curve(0, "giant swing: " + job.motion, "motion");
  if (ctx.already_stored_points().count({0, 0})) return;
  const Model model = appendix_b_gymnast();
  storage::SolutionPoint p =
      job.method == GiantSwingMethod::seed ? seed_point(model, job, ctx) : bezier_point(model, job, ctx);
  if (ctx.stop_reason() != StopReason::none) return;
  p.key = {0, 0};
  p.values["motion"] = job.motion;
  p.values["method"] = job.method == GiantSwingMethod::seed ? "seed" : "bezier";
  ctx.store_point(p);
}

}  // namespace

JobKind giant_swing_kind() {
  // No estimate: the seed's tasks take about a minute whatever the options.
  return typed_job_kind<GiantSwingJob>("giant_swing", {"giant_swing"}, giant_swing_job_fields(), parse_giant_swing_job,
                                       run_giant_swing, giant_swing_job_json);
}

}  // namespace cyclopt::jobs
