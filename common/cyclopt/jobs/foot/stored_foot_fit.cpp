#include "cyclopt/jobs/foot/stored_foot_fit.hpp"

#include "cyclopt/errors/spec_error.hpp"
#include "cyclopt/records/foot_fit_record.hpp"
#include "cyclopt/service/stored_references.hpp"

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

nlohmann::json with_stored_foot_fit(nlohmann::json spec, storage::ResultReader& store) {
  for (const StoredFitReference& r : stored_fit_references(spec)) {
    const std::string job_field = r.path + ".fit.job", model_field = r.path + ".fit.model";
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
    nlohmann::json& foot = spec[r.where];
    foot = fit.foot;
    foot["name"] = "fitted " + r.model + " (" + job_name + ")";
  }
  return spec;
}

}  // namespace cyclopt::jobs
