#include "cyclopt/jobs/walker/stored_start.hpp"

#include "cyclopt/records/walker_point_record.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/jobs/foot/stored_foot_fit.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/walker/virtual_constraints.hpp"

#include <limits>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

bool names_stored_point(const nlohmann::json& spec) { return spec.contains("start") && spec["start"].is_object(); }

int bezier_degree(const nlohmann::json& spec) {
  return optional_integer(spec, "", "bezier_degree", 3, 10).value_or(walker::WalkingConstants{}.bezier_degree);
}

struct StoredPointReference {
  std::int64_t job_id;
  storage::PointKey key;
};

StoredPointReference stored_point_reference(const nlohmann::json& s) {
  reject_unknown_keys(s, "start", {"job", "curve", "point"});
  if (!s.contains("job")) throw SpecError("start.job", "is required: the id of the job that stored the point");
  if (!s.contains("point")) throw SpecError("start.point", "is required: the point's index on its curve (>= 0)");
  constexpr int kMax = std::numeric_limits<int>::max();
  return {*optional_integer(s, "start", "job", 1, kMax),
          {optional_integer(s, "start", "curve", 0, kMax).value_or(0), *optional_integer(s, "start", "point", 0, kMax)}};
}

}  // namespace

nlohmann::json without_stored_start(nlohmann::json spec) {
  if (!names_stored_point(spec)) return spec;
  stored_point_reference(spec["start"]);
  spec.erase("start");
  return spec;
}

nlohmann::json with_stored_start(nlohmann::json spec, storage::ResultStore& store) {
  if (!names_stored_point(spec)) return spec;
  const nlohmann::json& s = spec["start"];
  const auto [job_id, key] = stored_point_reference(s);
  const std::string job_name = "job " + std::to_string(job_id);
  const std::optional<storage::JobRecord> stored = store.job(job_id);
  if (!stored) throw SpecError("start.job", "there is no " + job_name + " in this server's database");
  const nlohmann::json stored_spec = nlohmann::json::parse(runnable_spec_text(*stored), nullptr, false);
  if (stored->scene != "walker" || !stored_spec.is_object() || !stored_spec.contains("foot"))
    throw SpecError("start.job", job_name + " is a " + stored->scene + " " + stored->task + " job, not a walker gait job");
  const std::string where = "(curve " + std::to_string(key.curve_index) + ", point " + std::to_string(key.point_index) + ")";
  const std::optional<std::string> values = store.point_values(job_id, key);
  if (!values)
    throw SpecError(s.contains("curve") ? "start.curve" : "start.point",
                    job_name + " has no stored point " + where + "; it has " +
                        std::to_string(store.stored_points(job_id).size()) + " (cyclopt query " +
                        std::to_string(job_id) + " lists them)");
  records::WalkerPointRecord point;
  try {
    point = nlohmann::json::parse(*values).get<records::WalkerPointRecord>();
  } catch (const std::exception& e) {
    throw SpecError("start.point", "point " + where + " of " + job_name + " is not a walker point: " + e.what());
  }
  if (point.x.empty())
    throw SpecError("start.point", "point " + where + " of " + job_name + " holds no gait parameters x" +
                                       (point.gait ? "" : " (no gait was found there)"));
  if (!spec.contains("foot")) return spec;  // the walker fields' own check names "foot"
  const foot::FootSpec foot = foot_value(spec["foot"], "foot");
  const foot::FootSpec stored_foot = foot_value(stored_spec["foot"], "foot");
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

std::string runnable_spec_text(const storage::JobRecord& job) {
  const nlohmann::json spec = nlohmann::json::parse(job.spec_json, nullptr, false);
  const bool references = spec.is_object() && (names_stored_point(spec) || names_stored_foot_fit(spec));
  return references && !job.resolved_spec_json.empty() ? job.resolved_spec_json : job.spec_json;
}

}  // namespace cyclopt::jobs
