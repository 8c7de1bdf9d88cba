#pragma once
// Where a claimed job runs. The worker pool hands every job to one executor with the job's
// JobContext (store, progress, limits, cancellation stay the pool's): the local executor runs the
// job kind on the worker thread itself (the default), the Slurm executor (remote/slurm_executor.hpp)
// runs it as a batch job through a shared spool and feeds the results back into the context.
// Contract as JobKind::run: return normally when done or stopped, throw when the job failed.

#include "cyclopt/service/job_kind.hpp"
#include "cyclopt/storage/job_record.hpp"

#include <nlohmann/json.hpp>

namespace cyclopt::server {

class JobExecutor {
 public:
  virtual ~JobExecutor() = default;
  virtual void run(const storage::JobRecord& job, const nlohmann::json& spec, service::JobContext& ctx) const = 0;
};

class LocalExecutor final : public JobExecutor {
 public:
  explicit LocalExecutor(const service::JobKindRegistry& kinds) : kinds_(kinds) {}
  void run(const storage::JobRecord& job, const nlohmann::json& spec, service::JobContext& ctx) const override {
    const service::JobKind* kind = kinds_.find(job.task);
    if (!kind) throw std::runtime_error("task '" + job.task + "' is not available on this server");
    kind->run(spec, ctx);
  }

 private:
  const service::JobKindRegistry& kinds_;
};

}  // namespace cyclopt::server
