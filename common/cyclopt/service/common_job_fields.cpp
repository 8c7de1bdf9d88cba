#include "cyclopt/service/common_job_fields.hpp"

#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/spec_fields.hpp"

#include <algorithm>
#include <cmath>

namespace cyclopt::service {

namespace {

const std::vector<std::string> kSolverFields = {"solver", "max_iterations", "optimality_tolerance",
                                                "constraint_tolerance", "print_level"};
const std::vector<std::string> kLimitFields = {"max_wall_seconds", "max_iterations"};
constexpr double kMaxWallSeconds = 7 * 86400.0;
constexpr int kMaxIterationLimit = 1000000000;

SolverOverrides parse_solver(const nlohmann::json& spec) {
  SolverOverrides o;
  if (!spec.contains("solver")) return o;
  const nlohmann::json& s = object_value(spec["solver"], "solver");
  reject_unknown_keys(s, "solver", kSolverFields);
  if (s.contains("solver")) o.solver = enum_value(s["solver"], "solver.solver", {"ipopt", "sqp"});
  o.max_iterations = optional_integer(s, "solver", "max_iterations", 1, 100000);
  o.optimality_tolerance = optional_number(s, "solver", "optimality_tolerance", 1e-14, 1.0);
  o.constraint_tolerance = optional_number(s, "solver", "constraint_tolerance", 1e-14, 1.0);
  o.print_level = optional_integer(s, "solver", "print_level", 0, 12);
  return o;
}

RequestedLimits parse_limits(const nlohmann::json& spec) {
  RequestedLimits r;
  if (!spec.contains("limits")) return r;
  const nlohmann::json& l = object_value(spec["limits"], "limits");
  reject_unknown_keys(l, "limits", kLimitFields);
  if (l.contains("max_wall_seconds")) {  // (0, 604800]: a limit of 0 s would end the job before it began
    const nlohmann::json& v = l["max_wall_seconds"];
    const double x = v.is_number() ? v.get<double>() : 0.0;
    if (!v.is_number() || !std::isfinite(x) || !(x > 0.0) || x > kMaxWallSeconds)
      throw SpecError("limits.max_wall_seconds", "must be a number in (0, " + std::to_string(static_cast<int>(kMaxWallSeconds)) +
                                                     "] seconds, got " + v.dump());
    r.max_wall_seconds = x;
  }
  r.max_iterations = optional_integer(l, "limits", "max_iterations", 1, kMaxIterationLimit);
  return r;
}

}  // namespace

const std::vector<std::string>& common_job_field_names() {
  static const std::vector<std::string> v = {"scene", "task", "name", "objective", "solver", "limits"};
  return v;
}

CommonJobFields parse_common_job_fields(const nlohmann::json& spec) {
  CommonJobFields c;
  if (spec.contains("name")) c.name = string_value(spec["name"], "name", 200);
  if (spec.contains("objective")) c.objective = enum_value(spec["objective"], "objective", known_objectives());
  c.solver = parse_solver(spec);
  c.limits = parse_limits(spec);
  return c;
}

JobLimits effective_limits(const RequestedLimits& requested, const JobLimits& caps) {
  JobLimits l = caps;
  if (requested.max_wall_seconds) l.max_wall_seconds = std::min(caps.max_wall_seconds, *requested.max_wall_seconds);
  if (requested.max_iterations) l.max_iterations = std::min(caps.max_iterations, *requested.max_iterations);
  return l;
}

}  // namespace cyclopt::service
