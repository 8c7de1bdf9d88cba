#include "cyclopt/jobs/giant_swing/giant_swing_job_spec.hpp"

#include "cyclopt/io/task_spec_json.hpp"
#include "cyclopt/jobs/solver_fields.hpp"
#include "cyclopt/service/spec_fields.hpp"

#include <algorithm>
#include <map>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

using giant_swing::TaskKind;

const std::map<std::string, TaskKind>& motions() {
  static const std::map<std::string, TaskKind> m = {{"single", TaskKind::single_swing},
                                                    {"periodic", TaskKind::periodic_sequence},
                                                    {"accelerating", TaskKind::accelerating},
                                                    {"decelerating", TaskKind::decelerating}};
  return m;
}

const std::vector<std::string> kBezierKeys = {"free_coefficients", "steps", "min_rate_fraction"};
const std::vector<std::string> kCommonTaskKeys = {"name", "omega_deg_s", "initial_rate_deg_s", "rounds",
                                                  "alpha_min_deg", "alpha_max_deg"};
const std::vector<std::string> kSeedOnlyKeys = {"weights", "alpha_ddot_max_deg_s2", "relative_tolerance", "optimiser"};

}  // namespace

const std::vector<std::string>& giant_swing_job_fields() {
  static const std::vector<std::string> v = {"motion", "method", "options"};
  return v;
}

GiantSwingJob parse_giant_swing_job(const nlohmann::json& spec, const CommonJobFields& common) {
  GiantSwingJob job;
  std::vector<std::string> motion_names;
  for (const auto& [name, kind] : motions()) motion_names.push_back(name);
  if (!spec.contains("motion")) throw SpecError("motion", "is required (" + join(motion_names) + ")");
  job.motion = enum_value(spec["motion"], "motion", motion_names);
  if (spec.contains("method"))
    job.method = enum_value(spec["method"], "method", {"seed", "bezier"}) == "seed" ? GiantSwingMethod::seed
                                                                                     : GiantSwingMethod::bezier;
  const bool seed = job.method == GiantSwingMethod::seed;
  nlohmann::json options = nlohmann::json::object();
  if (spec.contains("options")) options = object_value(spec["options"], "options");
  std::vector<std::string> known = kCommonTaskKeys;
  const std::vector<std::string>& method_keys = seed ? kSeedOnlyKeys : kBezierKeys;
  known.insert(known.end(), method_keys.begin(), method_keys.end());
  reject_unknown_keys(options, "options", known);
  // The task fields go through the giant-swing task parser (ranges of giant_swing_task.schema.json).
  nlohmann::json task = {{"task", giant_swing::to_string(motions().at(job.motion))}};
  for (const auto& [key, value] : options.items())
    if (std::find(kBezierKeys.begin(), kBezierKeys.end(), key) == kBezierKeys.end()) task[key] = value;
  job.task = io::task_spec_from_json(task, "options");
  giant_swing::MinimumJerkProblemOptions& p = job.bezier.problem;
  if (auto n = optional_integer(options, "options", "free_coefficients", giant_swing::kMinFreeBezierCoefficients,
                                giant_swing::kMaxFreeBezierCoefficients))
    p.free_coefficients = *n;
  if (auto n = optional_integer(options, "options", "steps", 10, 2000)) p.steps = *n;
  if (auto f = optional_number(options, "options", "min_rate_fraction", 0.0, 0.9)) p.min_rate_fraction = *f;
  job.bezier.solver = solver_options(common.solver, giant_swing::minimum_jerk_solver_options());
  return job;
}

nlohmann::json giant_swing_job_json(const GiantSwingJob& job) {
  const bool seed = job.method == GiantSwingMethod::seed;
  const nlohmann::json task = io::to_json(job.task);
  nlohmann::json options = nlohmann::json::object();
  std::vector<std::string> keys = kCommonTaskKeys;
  if (seed) keys.insert(keys.end(), kSeedOnlyKeys.begin(), kSeedOnlyKeys.end());
  for (const std::string& key : keys)
    if (task.contains(key)) options[key] = task[key];
  nlohmann::json j = {{"motion", job.motion}, {"method", seed ? "seed" : "bezier"}};
  if (!seed) {
    const giant_swing::MinimumJerkProblemOptions& p = job.bezier.problem;
    options["free_coefficients"] = p.free_coefficients;
    options["steps"] = p.steps;
    options["min_rate_fraction"] = p.min_rate_fraction;
    j["solver"] = solver_json(job.bezier.solver);  // the seed method solves no NLP
  }
  j["options"] = options;
  return j;
}

}  // namespace cyclopt::jobs
