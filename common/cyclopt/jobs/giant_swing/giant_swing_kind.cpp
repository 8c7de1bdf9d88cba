// Job kind "giant_swing" (scene and task "giant_swing", seed 000; the spec's fields in
// giant_swing_job_spec.hpp): one point per job, the motion solved by the seed's method or the
// Bezier minimum-jerk NLP. The point's values (records::GiantSwingRecord): motion, method, the task,
// the rounds of the full model (end-of-round boundary values phi'/omega, alpha, alpha', friction,
// jerk, moment per completed round), rounds_completed, integrations, wall_seconds, and for seed
// the support values of M_alpha (Nm), score and stages; for bezier the free coefficients (rad),
// the reduced-model values, the solver summary and, for periodic, the Floquet multipliers of the
// one-step map at the handstand.
#include "cyclopt/giant_swing/one_step_map.hpp"
#include "cyclopt/giant_swing/seed_optimiser.hpp"
#include "cyclopt/io/seed_method_json.hpp"
#include "cyclopt/io/task_spec_json.hpp"
#include "cyclopt/jobs/giant_swing/giant_swing_job_spec.hpp"
#include "cyclopt/jobs/giant_swing/giant_swing_kinds.hpp"
#include "cyclopt/jobs/solver_progress.hpp"
#include "cyclopt/records/giant_swing_records.hpp"

#include <stdexcept>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

using namespace giant_swing;

// The motion in the full model, round by round, into `r`.
void add_rounds(const SimulationResult& sim, double omega, records::GiantSwingRecord& r) {
  for (const RoundResult& round : sim.rounds) r.rounds.push_back(io::round_record(round, omega));
  r.rounds_completed = static_cast<int>(sim.rounds.size());
  if (sim.failed) {
    r.failure_reason = sim.failure_reason;
    r.failure_phi_deg = sim.failure_phi * kDegPerRad;
  }
}

// The point (its values but the motion and the method) of the seed's method.
storage::SolutionPoint seed_point(const Model& model, const GiantSwingJob& job, JobContext& ctx, records::GiantSwingRecord& values) {
  ctx.report_progress({.curve_id = 0, .points_total = 1, .message = "seed method, " + job.motion});
  const SeedMethodResult r = optimise_seed_method(model, job.task);
  ctx.count_iterations(r.integrations);
  records::SeedMethodRecord seed;
  seed.score = r.best.score;
  seed.support_values_Nm.assign(r.torque.support_values.begin(), r.torque.support_values.end());
  seed.failed = r.best.simulation.failed;
  for (const StageReport& s : r.stages) seed.stages.push_back({s.support_points, s.step, s.score, s.evaluations});
  seed.model_integrations = r.integrations;
  seed.budget_exhausted = r.budget_exhausted;
  values.seed = seed;
  values.task = io::to_json(job.task);
  add_rounds(r.best.simulation, job.task.omega, values);
  values.integrations = r.integrations;
  values.wall_seconds = r.wall_seconds;
  storage::SolutionPoint p;
  p.objective = r.best.score;
  p.iterations = r.integrations;
  p.status = r.best.simulation.failed && r.best.simulation.rounds.empty() ? "failed" : "ok";
  return p;
}

// The point (its values but the motion and the method) of the Bezier minimum-jerk swing.
storage::SolutionPoint bezier_point(const Model& model, const GiantSwingJob& job, JobContext& ctx, records::GiantSwingRecord& values) {
  MinimumJerkSettings settings = job.bezier;
  settings.solver.on_iteration =
      solver_progress(ctx, {.curve_id = 0, .points_total = 1, .message = "bezier minimum jerk, " + job.motion});
  settings.solver.should_stop = stop_predicate(ctx);
  // periodic: the closed swing from and to omega, repeated (its start rate is omega).
  const MinimumJerkResult r = solve_minimum_jerk(model, job.task, settings);
  if (r.coefficients.size() == 0) throw std::runtime_error("giant swing (bezier): " + r.message);
  records::MinimumJerkRecord bezier;
  bezier.coefficients_rad.assign(r.coefficients.begin(), r.coefficients.end());
  bezier.free_coefficients = static_cast<int>(r.coefficients.size());
  bezier.jerk_rad2_s5 = r.jerk;
  bezier.start_jerk_rad2_s5 = r.start_jerk;
  bezier.phi_rate_over_omega_minus_1 = r.boundary_error;
  bezier.friction_loss_J = r.friction_loss;
  bezier.moment_Nm2_s = r.torque_integral;
  bezier.solver = nlp::to_string(settings.solver.solver);
  bezier.termination = nlp::to_string(r.summary.termination);
  bezier.success = r.summary.success();
  bezier.iterations = r.summary.iterations;
  bezier.message = r.message;
  values.task = io::to_json(job.task);
  values.integrations = r.integrations;
  values.wall_seconds = r.wall_seconds;
  // The motion in the full model under the constraint-enforcing hip torque.
  const VirtualConstraintTorque law(bezier_from_free(r.coefficients), kConstraintGainP, kConstraintGainD, model);
  SimulationOptions o = simulation_options(job.task);
  o.integrator.relative_tolerance = 1e-12;
  o.integrator.absolute_tolerance = 1e-14;
  add_rounds(simulate_swings(model, law, initial_state(job.task), job.task.rounds, o), job.task.omega, values);
  if (job.task.kind == TaskKind::periodic_sequence) {
    const OneStepJacobian J = one_step_jacobian(model, law, SectionState(job.task.omega, 0.0, 0.0), o);
    if (J.ok)
      for (const auto& lambda : floquet_multipliers(J.jacobian)) bezier.floquet_multiplier_moduli.push_back(std::abs(lambda));
  }
  values.bezier = bezier;
  storage::SolutionPoint p;
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
  records::GiantSwingRecord values;
  values.motion = job.motion;
  values.method = job.method == GiantSwingMethod::seed ? "seed" : "bezier";
  storage::SolutionPoint p =
      job.method == GiantSwingMethod::seed ? seed_point(model, job, ctx, values) : bezier_point(model, job, ctx, values);
  if (ctx.stop_reason() != StopReason::none) return;
  p.key = {0, 0};
  p.set_values(values);
  ctx.store_point(p);
}

}  // namespace

JobKind giant_swing_kind() {
  // No estimate: the seed's tasks take about a minute whatever the options.
  return typed_job_kind<GiantSwingJob>("giant_swing", {"giant_swing"}, giant_swing_job_fields(), parse_giant_swing_job,
                                       run_giant_swing, giant_swing_job_json);
}

}  // namespace cyclopt::jobs
