#include "cyclopt/io/seed_method_json.hpp"

#include "cyclopt/io/task_spec_json.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace cyclopt::io {

using namespace giant_swing;

records::SwingRoundRecord round_record(const RoundResult& round, double omega) {
  return {.phi_rate_over_omega = round.phi_rate / omega,
          .alpha_deg = round.alpha * kDegPerRad,
          .alpha_rate_deg_s = round.alpha_rate * kDegPerRad,
          .duration_s = round.duration,
          .friction_loss_J = round.friction_loss,
          .jerk_rad2_s5 = round.jerk,
          .moment_Nm2_s = round.torque_integral};
}

nlohmann::json to_json(const RoundResult& round, double omega) { return round_record(round, omega); }

nlohmann::json to_json(const SeedMethodResult& r, const TaskSpec& spec) {
  nlohmann::json j;
  j["task"] = to_json(spec);
  j["method"] = "seed: piecewise-linear M_alpha(phi), multistage Nelder-Mead";
  j["score"] = r.best.score;
  j["support_values_Nm"] = std::vector<double>(r.torque.support_values.begin(), r.torque.support_values.end());
  nlohmann::json rounds = nlohmann::json::array();
  for (const RoundResult& round : r.best.simulation.rounds) rounds.push_back(to_json(round, spec.omega));
  j["rounds"] = rounds;
  j["failed"] = r.best.simulation.failed;
  if (r.best.simulation.failed) {
    j["failure_reason"] = r.best.simulation.failure_reason;
    j["failure_phi_deg"] = r.best.simulation.failure_phi * kDegPerRad;
  }
  nlohmann::json stages = nlohmann::json::array();
  for (const StageReport& s : r.stages)
    stages.push_back({{"support_points", s.support_points}, {"step_Nm", s.step}, {"score", s.score},
                      {"evaluations", s.evaluations}});
  j["stages"] = stages;
  j["model_integrations"] = r.integrations;
  j["budget_exhausted"] = r.budget_exhausted;
  j["wall_seconds"] = r.wall_seconds;
  return j;
}

}  // namespace cyclopt::io
