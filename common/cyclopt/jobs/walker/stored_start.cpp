#include "cyclopt/jobs/walker/stored_start.hpp"

#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/records/walker_point_record.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/service/stored_references.hpp"
#include "cyclopt/walker/virtual_constraints.hpp"

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

int bezier_degree(const nlohmann::json& spec) {
  return optional_integer(spec, "", "bezier_degree", 3, 10).value_or(walker::WalkingConstants{}.bezier_degree);
}

// The foot whose gait a point of `job` holds: a gait job's foot; of a foot_comparison, curve 1's
// the reference, curve 1 + k's its k-th foot and curve 0's the foot the point names (the best foot
// at its speed), all from the resolved spec, which lists every foot with its parameters. Null
// for jobs without gaits and for a comparison's summary curve.
nlohmann::json stored_point_foot(const storage::JobRecord& job, const nlohmann::json& stored_spec, int curve,
                                 const nlohmann::json& values) {
  if (job.scene != "walker" || !stored_spec.is_object()) return nullptr;
  if (stored_spec.contains("foot")) return stored_spec["foot"];
  if (job.task != "foot_comparison") return nullptr;
  const nlohmann::json resolved = nlohmann::json::parse(job.resolved_spec_json, nullptr, false);
  if (!resolved.is_object() || !resolved.contains("reference") || !resolved.contains("feet")) return nullptr;
  nlohmann::json feet = nlohmann::json::array({resolved["reference"]});
  for (const nlohmann::json& f : resolved["feet"]) feet.push_back(f);
  if (curve >= 1 && curve <= static_cast<int>(feet.size())) return feet[curve - 1];
  if (curve != 0 || !values.contains("foot")) return nullptr;
  for (const nlohmann::json& f : feet)
    if (f.value("name", "") == values["foot"]) return f;
  return nullptr;
}

}  // namespace

nlohmann::json with_stored_start(nlohmann::json spec, storage::ResultReader& store) {
  const std::optional<StoredPointReference> reference = stored_point_reference(spec);
  if (!reference) return spec;
  const auto [job_id, key, curve_given] = *reference;
  const std::string job_name = "job " + std::to_string(job_id);
  const std::optional<storage::JobRecord> stored = store.job(job_id);
  if (!stored) throw SpecError("start.job", "there is no " + job_name + " in this server's database");
  const nlohmann::json stored_spec = nlohmann::json::parse(runnable_spec_text(*stored), nullptr, false);
  const bool gaits = stored->scene == "walker" && stored_spec.is_object() &&
                     (stored_spec.contains("foot") || stored->task == "foot_comparison");
  if (!gaits)
    throw SpecError("start.job", job_name + " is a " + stored->scene + " " + stored->task + " job, not a walker gait job");
  const std::string where = "(curve " + std::to_string(key.curve_index) + ", point " + std::to_string(key.point_index) + ")";
  const std::optional<std::string> values = store.point_values(job_id, key);
  if (!values)
    throw SpecError(curve_given ? "start.curve" : "start.point",
                    job_name + " has no stored point " + where + "; it has " +
                        std::to_string(store.stored_points(job_id).size()) + " (cyclopt query " +
                        std::to_string(job_id) + " lists them)");
  const nlohmann::json point_json = nlohmann::json::parse(*values, nullptr, false);
  const nlohmann::json point_foot = stored_point_foot(*stored, stored_spec, key.curve_index, point_json);
  if (point_foot.is_null())
    throw SpecError(curve_given ? "start.curve" : "start.point",
                    "point " + where + " of " + job_name + " is no gait of one foot (a foot_comparison's gaits are on " +
                        "curve 1, the reference, and curves 2, 3, ..., its feet)");
  records::WalkerPointRecord point;
  try {
    point = point_json.get<records::WalkerPointRecord>();
  } catch (const std::exception& e) {
    throw SpecError("start.point", "point " + where + " of " + job_name + " is not a walker point: " + e.what());
  }
  if (point.x.empty())
    throw SpecError("start.point", "point " + where + " of " + job_name + " holds no gait parameters x" +
                                       (point.gait ? "" : " (no gait was found there)"));
  if (!spec.contains("foot")) return spec;  // the walker fields' own check names "foot"
  const foot::FootSpec foot = io::foot_value(spec["foot"], "foot");
  const foot::FootSpec stored_foot = io::foot_value(point_foot, "foot");
  if (foot.model != stored_foot.model)
    throw SpecError("start.job", job_name + " is for the foot model " + std::string(foot::to_string(stored_foot.model)) +
                                     ", this job's foot is " + std::string(foot::to_string(foot.model)) +
                                     ": a gait starts only a walker of the same foot model");
  const int degree = bezier_degree(spec);
  if (bezier_degree(stored_spec) != degree)
    throw SpecError("start.job", job_name + " has bezier_degree " + std::to_string(bezier_degree(stored_spec)) +
                                     ", this job " + std::to_string(degree) + ": the gait parameters x do not match");
  walker::WalkingConstants constants;
  constants.bezier_degree = degree;
  const int n = walker::gait_parameter_count(walker::make_walker_model(foot, constants).joint_count, degree);
  if (static_cast<int>(point.x.size()) < n)
    throw SpecError("start.point", "point " + where + " of " + job_name + " holds " + std::to_string(point.x.size()) +
                                       " numbers, fewer than the " + std::to_string(n) + " gait parameters x");
  spec["start"] = std::vector<double>(point.x.begin(), point.x.begin() + n);
  return spec;
}

}  // namespace cyclopt::jobs
