#include "cyclopt/records/giant_swing_records.hpp"

namespace cyclopt::records {

void to_json(nlohmann::json& j, const SwingRoundRecord& r) {
  j = {{"phi_rate_over_omega", r.phi_rate_over_omega},
       {"alpha_deg", r.alpha_deg},
       {"alpha_rate_deg_s", r.alpha_rate_deg_s},
       {"duration_s", r.duration_s},
       {"friction_loss_J", r.friction_loss_J},
       {"jerk_rad2_s5", r.jerk_rad2_s5},
       {"moment_Nm2_s", r.moment_Nm2_s}};
}

void from_json(const nlohmann::json& j, SwingRoundRecord& r) {
  const std::string n = "values.rounds";
  r = {number(j, n, "phi_rate_over_omega"), number(j, n, "alpha_deg"),     number(j, n, "alpha_rate_deg_s"),
       number(j, n, "duration_s"),          number(j, n, "friction_loss_J"), number(j, n, "jerk_rad2_s5"),
       number(j, n, "moment_Nm2_s")};
}

void to_json(nlohmann::json& j, const GiantSwingRecord& g) {
  j = {{"motion", g.motion}, {"method", g.method}, {"task", g.task}, {"rounds", g.rounds},
       {"rounds_completed", g.rounds_completed}, {"integrations", g.integrations}, {"wall_seconds", g.wall_seconds}};
  if (g.failure_reason) j["failure_reason"] = *g.failure_reason;
  if (g.failure_phi_deg) j["failure_phi_deg"] = *g.failure_phi_deg;
  if (const auto& s = g.seed) {
    j["score"] = s->score;
    j["support_values_Nm"] = s->support_values_Nm;
    j["failed"] = s->failed;
    j["stages"] = nlohmann::json::array();
    for (const SeedStageRecord& t : s->stages)
      j["stages"].push_back(
          {{"support_points", t.support_points}, {"step_Nm", t.step_Nm}, {"score", t.score}, {"evaluations", t.evaluations}});
    j["model_integrations"] = s->model_integrations;
    j["budget_exhausted"] = s->budget_exhausted;
  }
  if (const auto& b = g.bezier) {
    j["coefficients_rad"] = b->coefficients_rad;
    j["free_coefficients"] = b->free_coefficients;
    j["reduced_model"] = {{"jerk_rad2_s5", b->jerk_rad2_s5},
                          {"start_jerk_rad2_s5", b->start_jerk_rad2_s5},
                          {"phi_rate_over_omega_minus_1", b->phi_rate_over_omega_minus_1},
                          {"friction_loss_J", b->friction_loss_J},
                          {"moment_Nm2_s", b->moment_Nm2_s}};
    j["solver"] = {{"solver", b->solver},
                   {"termination", b->termination},
                   {"success", b->success},
                   {"iterations", b->iterations},
                   {"message", b->message}};
    if (!b->floquet_multiplier_moduli.empty()) j["floquet_multiplier_moduli"] = b->floquet_multiplier_moduli;
  }
}

void from_json(const nlohmann::json& j, GiantSwingRecord& g) {
  const std::string r = "values";
  g = GiantSwingRecord{};
  g.motion = text(j, r, "motion");
  g.method = text(j, r, "method");
  g.task = member(j, r, "task");
  g.rounds = member(j, r, "rounds").get<std::vector<SwingRoundRecord>>();
  g.rounds_completed = integer(j, r, "rounds_completed");
  g.failure_reason = optional_text(j, r, "failure_reason");
  g.failure_phi_deg = optional_number(j, r, "failure_phi_deg");
  g.integrations = integer(j, r, "integrations");
  g.wall_seconds = number(j, r, "wall_seconds");
  if (g.method == "seed") {
    SeedMethodRecord s;
    s.score = number(j, r, "score");
    s.support_values_Nm = numbers(j, r, "support_values_Nm");
    s.failed = boolean(j, r, "failed");
    for (const nlohmann::json& t : member(j, r, "stages"))
      s.stages.push_back({integer(t, "values.stages", "support_points"), number(t, "values.stages", "step_Nm"),
                          number(t, "values.stages", "score"), integer(t, "values.stages", "evaluations")});
    s.model_integrations = integer(j, r, "model_integrations");
    s.budget_exhausted = boolean(j, r, "budget_exhausted");
    g.seed = s;
  } else {
    MinimumJerkRecord b;
    b.coefficients_rad = numbers(j, r, "coefficients_rad");
    b.free_coefficients = integer(j, r, "free_coefficients");
    const nlohmann::json& m = member(j, r, "reduced_model");
    const std::string rm = "values.reduced_model";
    b.jerk_rad2_s5 = number(m, rm, "jerk_rad2_s5");
    b.start_jerk_rad2_s5 = number(m, rm, "start_jerk_rad2_s5");
    b.phi_rate_over_omega_minus_1 = number(m, rm, "phi_rate_over_omega_minus_1");
    b.friction_loss_J = number(m, rm, "friction_loss_J");
    b.moment_Nm2_s = number(m, rm, "moment_Nm2_s");
    const nlohmann::json& s = member(j, r, "solver");
    const std::string rs = "values.solver";
    b.solver = text(s, rs, "solver");
    b.termination = text(s, rs, "termination");
    b.success = boolean(s, rs, "success");
    b.iterations = integer(s, rs, "iterations");
    b.message = text(s, rs, "message");
    if (j.contains("floquet_multiplier_moduli")) b.floquet_multiplier_moduli = numbers(j, r, "floquet_multiplier_moduli");
    g.bezier = b;
  }
}

}  // namespace cyclopt::records
