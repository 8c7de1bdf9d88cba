#include "cyclopt/jobs/walker/walker_job_spec.hpp"

#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/jobs/solver_fields.hpp"
#include "cyclopt/jobs/walker/design_bounds_spec.hpp"
#include "cyclopt/jobs/walker/walker_job_cost.hpp"
#include "cyclopt/jobs/walker/walker_job_json.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/service/value_range.hpp"
#include "cyclopt/walker/model_parameters.hpp"
#include "cyclopt/walker/virtual_constraints.hpp"

#include <algorithm>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

std::vector<std::string> walker_job_fields(bool sweep) {
  return {"foot", sweep ? "speeds" : "speed", "points", "bezier_degree", "quadrature", "positive_power_band",
          "free_parameters", "design_bounds", "start", "multistart"};
}

WalkerJob parse_walker_job(const nlohmann::json& spec, const CommonJobFields& common, bool sweep) {
  WalkerJob job;
  if (!spec.contains("foot")) throw SpecError("foot", "is required: a preset name or a foot spec object");
  job.foot = io::foot_value(spec["foot"], "foot");
  const std::string speed_key = sweep ? "speeds" : "speed";
  if (!spec.contains(speed_key))
    throw SpecError(speed_key, "is required (m/s, in [" + std::to_string(kMinWalkingSpeed) + ", " +
                                   std::to_string(kMaxWalkingSpeed) + "])");
  job.speeds = sweep ? parse_value_range(spec[speed_key], speed_key, kMinWalkingSpeed, kMaxWalkingSpeed)
                     : std::vector<double>{number_value(spec[speed_key], speed_key, kMinWalkingSpeed, kMaxWalkingSpeed)};
  job.constants.points = optional_integer(spec, "", "points", kMinGaitPoints, kMaxGaitPoints).value_or(job.constants.points);
  job.constants.bezier_degree = optional_integer(spec, "", "bezier_degree", 3, 10).value_or(job.constants.bezier_degree);
  if (common.objective)
    job.problem.objective = *common.objective == "f_usq" ? walker::Objective::squared_torque : walker::Objective::mechanical;
  if (spec.contains("quadrature"))
    job.problem.quadrature = enum_value(spec["quadrature"], "quadrature", {"trapezoid", "corrected_trapezoid"}) ==
                                     "trapezoid"
                                 ? walker::Quadrature::trapezoid
                                 : walker::Quadrature::corrected_trapezoid;
  job.solver = solver_options(common.solver, nlp::seed_table_6_2_options());  // the seed's SQP by default
  const bool trapezoid = job.problem.quadrature == walker::Quadrature::trapezoid;
  const bool ipopt = job.solver.solver == nlp::SolverKind::ipopt;
  job.problem.positive_power_band = optional_number(spec, "", "positive_power_band", 0.0, walker::kMaxPositivePowerBand)
                                        .value_or(ipopt && trapezoid ? kIpoptPositivePowerBand : job.problem.positive_power_band);
  if (job.problem.positive_power_band > 0.0 && !trapezoid)
    throw SpecError("positive_power_band", "> 0 needs \"quadrature\": \"trapezoid\"");
  const walker::WalkerModel<double> model = job.model();
  if (spec.contains("free_parameters")) {
    const nlohmann::json& fp = spec["free_parameters"];
    if (!fp.is_array()) throw SpecError("free_parameters", "must be an array of model parameter names");
    const std::vector<std::string> names = walker::model_parameter_names(model);
    for (std::size_t i = 0; i < fp.size(); ++i) {
      const std::string field = "free_parameters[" + std::to_string(i) + "]";
      const std::string name = enum_value(fp[i], field, names);
      if (walker::follows_foot_geometry(model, walker::model_parameter_index(model, name)))
        throw SpecError(field, "'" + name + "' follows the foot geometry when foot.density is given (seed 001 appendix "
                               "E); free the foot parameters or \"density\" instead");
      job.problem.free_parameters.push_back(name);
    }
  }
  if (spec.contains("design_bounds")) apply_design_bounds(spec["design_bounds"], "design_bounds", job);  // (10.1)
  if (spec.contains("start")) {
    const nlohmann::json& s = spec["start"];
    const int n = walker::gait_parameter_count(model.joint_count, model.constants.bezier_degree);
    if (!s.is_array() || static_cast<int>(s.size()) != n)
      throw SpecError("start", "must be an array of " + std::to_string(n) + " gait parameters (alpha_2 .. alpha_tilde_M, rad)");
    Eigen::VectorXd x(n);
    for (int i = 0; i < n; ++i) x(i) = number_value(s[i], "start[" + std::to_string(i) + "]", -20.0, 20.0);
    job.start = x;
  }
  if (spec.contains("multistart")) {
    const nlohmann::json& m = object_value(spec["multistart"], "multistart");
    reject_unknown_keys(m, "multistart", {"starts", "seed", "seeds", "scale"});
    job.starts = optional_integer(m, "multistart", "starts", 1, 1000).value_or(job.starts);
    if (m.contains("seed") && m.contains("seeds")) throw SpecError("multistart.seeds", "give seed or seeds, not both");
    if (m.contains("seeds")) {
      const nlohmann::json& s = m["seeds"];
      if (!s.is_array() || s.empty() || s.size() > static_cast<std::size_t>(kMaxSeeds))
        throw SpecError("multistart.seeds", "must be an array of 1 to " + std::to_string(kMaxSeeds) + " distinct seeds in " +
                                                range_text(0, 2147483647));
      job.seeds.clear();
      for (std::size_t i = 0; i < s.size(); ++i) {
        const auto seed = static_cast<std::uint64_t>(integer_value(s[i], "multistart.seeds[" + std::to_string(i) + "]", 0, 2147483647));
        if (std::find(job.seeds.begin(), job.seeds.end(), seed) != job.seeds.end())
          throw SpecError("multistart.seeds[" + std::to_string(i) + "]", "repeats seed " + std::to_string(seed));
        job.seeds.push_back(seed);
      }
    } else {
      job.seeds = {static_cast<std::uint64_t>(optional_integer(m, "multistart", "seed", 0, 2147483647).value_or(1))};
    }
    if (!sweep && job.seeds.size() > 1)
      throw SpecError("multistart.seeds", "several seeds need a task that searches once per seed (sweep, foot_comparison, "
                                          "foot_design); give one seed");
    job.scale = optional_number(m, "multistart", "scale", 1e-6, 1.0).value_or(job.scale);
  }
  return job;
}

JobKind one_speed_kind(const std::string& task, bool random_starts, std::function<void(const WalkerJob&, JobContext&)> run) {
  return typed_job_kind<WalkerJob>(
      task, {"walker"}, walker_job_fields(false),
      [](const nlohmann::json& spec, const CommonJobFields& common) { return parse_walker_job(spec, common, false); },
      std::move(run), [random_starts](const WalkerJob& job) { return walker_job_json(job, false, random_starts); },
      [task](const WalkerJob& job) { return walker_job_cost(job, task, 1, 0); });
}

}  // namespace cyclopt::jobs
