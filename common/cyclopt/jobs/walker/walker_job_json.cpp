#include "cyclopt/jobs/walker/walker_job_json.hpp"

#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/jobs/solver_fields.hpp"

namespace cyclopt::jobs {

records::WalkerSetupRecord walker_setup(const WalkerJob& job) {
  return {.foot = io::to_json(job.foot),
          .points = job.constants.points,
          .bezier_degree = job.constants.bezier_degree,
          .objective = job.problem.objective == walker::Objective::squared_torque ? "f_usq" : "f_mech",
          .design_speed = std::nullopt};
}

nlohmann::json walker_job_json(const WalkerJob& job, bool sweep, bool random_starts) {
  nlohmann::json j = walker_setup(job);
  if (sweep)
    j["speeds"] = job.speeds;
  else
    j["speed"] = job.speeds.front();
  j["quadrature"] = job.problem.quadrature == walker::Quadrature::trapezoid ? "trapezoid" : "corrected_trapezoid";
  j["positive_power_band"] = job.problem.positive_power_band;
  j["free_parameters"] = job.problem.free_parameters;
  if (job.problem.design_bounds) {
    const foot::DesignBounds& b = *job.problem.design_bounds;
    nlohmann::json db = nlohmann::json::object();
    if (job.foot.model == foot::FootModel::hmt) db["toe_within_height"] = b.toe_within_height;  // HM feet have no toe
    for (const foot::DesignBoundField& f : foot::design_bound_fields(job.foot.model)) db[f.name] = b.*(f.value);
    j["design_bounds"] = db;
  }
  if (job.start) j["start"] = std::vector<double>(job.start->data(), job.start->data() + job.start->size());
  j["solver"] = solver_json(job.solver);
  if (random_starts) {
    j["multistart"] = {{"starts", job.starts}, {"scale", job.scale}};
    if (job.seeds.size() == 1)
      j["multistart"]["seed"] = job.seeds.front();
    else
      j["multistart"]["seeds"] = job.seeds;
  }
  return j;
}

}  // namespace cyclopt::jobs
