#include "cyclopt/jobs/foot/stored_foot_fit.hpp"

#include "cyclopt/records/foot_fit_record.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/storage/solution_point.hpp"

#include <functional>
#include <limits>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

bool is_reference(const nlohmann::json& foot) { return foot.is_object() && foot.contains("fit"); }

// Calls `f(foot, path)` for every foot field of `spec` that names a stored fit.
void for_each_reference(nlohmann::json& spec, const std::function<void(nlohmann::json&, const std::string&)>& f) {
  if (!spec.is_object()) return;
  for (const char* key : {"foot", "reference"})
    if (spec.contains(key) && is_reference(spec[key])) f(spec[key], key);
  if (spec.contains("feet") && spec["feet"].is_array())
    for (std::size_t i = 0; i < spec["feet"].size(); ++i)
      if (is_reference(spec["feet"][i])) f(spec["feet"][i], "feet[" + std::to_string(i) + "]");
}

struct FitReference {
  std::int64_t job_id = 0;
  std::string model;
};

FitReference fit_reference(const nlohmann::json& foot, const std::string& path) {
  reject_unknown_keys(foot, path, {"fit"});
  const std::string at = path + ".fit";
  const nlohmann::json& fit = object_value(foot["fit"], at);
  reject_unknown_keys(fit, at, {"job", "model"});
  if (!fit.contains("job")) throw SpecError(at + ".job", "is required: the id of a foot_fit job");
  FitReference r;
  r.job_id = *optional_integer(fit, at, "job", 1, std::numeric_limits<int>::max());
  r.model = fit.contains("model") ? enum_value(fit["model"], at + ".model", {"HM", "HMT"}) : "HMT";
  return r;
}

}  // namespace

bool names_stored_foot_fit(const nlohmann::json& spec) {
  bool any = false;
  nlohmann::json copy = spec;
  for_each_reference(copy, [&](nlohmann::json&, const std::string&) { any = true; });
  return any;
}

void check_stored_foot_fit_references(const nlohmann::json& spec) {
  nlohmann::json copy = spec;
  for_each_reference(copy, [](nlohmann::json& foot, const std::string& path) { fit_reference(foot, path); });
}

nlohmann::json with_stored_foot_fit(nlohmann::json spec, storage::ResultStore& store) {
  for_each_reference(spec, [&](nlohmann::json& foot, const std::string& path) {
    const FitReference r = fit_reference(foot, path);
    const std::string job_field = path + ".fit.job", model_field = path + ".fit.model";
    const std::string job_name = "job " + std::to_string(r.job_id);
    const std::optional<storage::JobRecord> job = store.job(r.job_id);
    if (!job) throw SpecError(job_field, "there is no " + job_name + " in this server's database");
    if (job->task != "foot_fit")
      throw SpecError(job_field, job_name + " is a " + job->scene + " " + job->task + " job, not a foot_fit job");
    if (job->state == storage::JobState::queued || job->state == storage::JobState::running)
      throw SpecError(job_field, job_name + " is " + std::string(storage::to_string(job->state)) +
                                     ": its fits are stored when it has finished (cyclopt watch " +
                                     std::to_string(r.job_id) + ")");
    const storage::PointKey key{0, r.model == "HM" ? 0 : 1};
    const std::optional<std::string> values = store.point_values(r.job_id, key);
    if (!values)
      throw SpecError(model_field, job_name + " (" + std::string(storage::to_string(job->state)) + ") stored no " +
                                       r.model + " fit");
    records::FootFitRecord fit;
    try {
      fit = nlohmann::json::parse(*values).get<records::FootFitRecord>();
    } catch (const std::exception& e) {
      throw SpecError(model_field, "the " + r.model + " point of " + job_name + " is not a foot fit: " + e.what());
    }
    if (!fit.converged)
      throw SpecError(model_field, "the " + r.model + " fit of " + job_name + " did not converge (" + fit.message +
                                       "): it is no fitted foot");
    foot = fit.foot;
    foot["name"] = "fitted " + r.model + " (" + job_name + ")";
  });
  return spec;
}

}  // namespace cyclopt::jobs
