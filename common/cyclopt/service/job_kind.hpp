#pragma once
// Pluggable job kinds. A job spec's "task" selects a JobKind from the registry. The spec is
// parsed and validated once (validate_job_spec, job_spec.hpp): the common fields into
// CommonJobFields, the kind's own fields by its parse() into a plain struct of the kind's choosing.
// The server keeps that typed result from the submission to the worker that runs it; run() and
// estimate() get the struct, never JSON.
//
// Adding a kind (e.g. the walker's speed sweep) takes ~25 lines:
//
//   // walker_sweep_kind.hpp
//   service::JobKind walker_sweep_kind();
//
//   // walker_sweep_kind.cpp
//   struct SweepJob {
//     std::vector<double> speeds;
//     nlp::SolverOptions solver;
//   };
//
//   SweepJob parse_sweep(const nlohmann::json& spec, const CommonJobFields& common) {
//     if (!spec.contains("speeds")) throw SpecError("speeds", "is required (m/s, \"lo:step:hi\")");
//     return {parse_value_range(spec["speeds"], "speeds", 0.05, 5.0),  // throws SpecError naming the field
//             solver_options(common.solver, nlp::seed_table_6_2_options())};  // jobs/solver_fields.hpp
//   }
//
//   nlohmann::json resolve_sweep(const SweepJob& job) {   // every default filled in
//     return {{"speeds", job.speeds}, {"solver", solver_json(job.solver)}};
//   }
//
//   void run_sweep(const SweepJob& job, JobContext& ctx) {
//     ctx.announce(int(job.speeds.size()));
//     ctx.add_curve(0, "speed sweep", "speed");
//     const auto done = ctx.already_stored_points();
//     for (int i = 0; i < int(job.speeds.size()); ++i) {
//       if (done.count({0, i})) continue;                    // resumed job: already solved
//       if (ctx.stop_reason() != StopReason::none) return;
//       // ... solve with job.solver, whose on_iteration is solver_progress(ctx, ...) and
//       //     should_stop stop_predicate(ctx) (solver_progress.hpp) ...
//       storage::SolutionPoint p;
//       p.key = {0, i};
//       p.parameter = job.speeds[i];
//       p.objective = summary.objective;                    // + values, status, trajectory
//       ctx.store_point(p);
//     }
//   }
//
//   service::JobKind walker_sweep_kind() {
//     return typed_job_kind<SweepJob>("sweep", {"walker"}, {"speeds"}, parse_sweep, run_sweep, resolve_sweep);
//   }
//
// and one line in builtin_job_kinds.cpp: registry.add(walker_sweep_kind());
//
// Contract for parse(): throws SpecError naming the first invalid field and its admissible range;
// everything else it throws is a server error. It is called once per submission, and once more
// only where a job is run from its stored text (after a server restart, in cyclopt-worker).
//
// Contract for resolve(): parse() of what it returns (with the common fields) gives the same
// spec, so that a stored resolved spec, submitted again, is the same job (resolved_spec.hpp).
//
// Contract for estimate(): kinds whose cost grows with their spec (grid size, starts, speeds)
// provide it.
//
// Contract for run(): it returns normally when all points are stored or when stop_reason() became
// non-none (the server then decides the job's state); it throws (any std::exception) only when
// the job failed — the message is stored. It must be re-entrant (several workers run jobs of the
// same kind) and must not keep state between calls: everything a resumed job needs is in the store.

#include "cyclopt/service/common_job_fields.hpp"
#include "cyclopt/service/job_context.hpp"
#include "cyclopt/service/job_cost.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace cyclopt::service {

// A kind's parsed spec, type-erased; typed_job_kind() gives each kind its own type back.
class KindSpec {
 public:
  virtual ~KindSpec() = default;
};

template <class Spec>
class KindSpecOf final : public KindSpec {
 public:
  explicit KindSpecOf(Spec spec) : spec_(std::move(spec)) {}
  const Spec& spec() const { return spec_; }

 private:
  const Spec spec_;
};

struct JobKind {
  std::string task;                       // the spec's "task"
  std::vector<std::string> scenes;        // admissible "scene" values
  std::vector<std::string> fields;        // top-level spec keys the kind reads (besides the common ones)
  std::function<std::shared_ptr<const KindSpec>(const nlohmann::json& spec, const CommonJobFields& common)> parse;
  std::function<void(const KindSpec& spec, JobContext& ctx)> run;
  // Expected time and memory of a parsed spec, checked against the server's limits before the job
  // is queued (job_cost.hpp); empty: the kind's jobs are cheap (seconds, little memory).
  std::function<JobCost(const KindSpec& spec)> estimate;
  // The kind's fields of a parsed spec with every default filled in, in the spec's own form (so
  // that submitting them again gives the same job), stored with the job (resolved_spec.hpp).
  // Every kind has one (JobKindRegistry::add checks).
  std::function<nlohmann::json(const KindSpec& spec)> resolve;
  // Kinds whose run() splits the job into work units (JobContext::run_units, issue 18): computes
  // one unit, as cyclopt-worker does for a unit run elsewhere. Empty: the job is one piece of work.
  std::function<void(const KindSpec& spec, const WorkUnit& unit, JobContext& ctx)> run_unit;
};

// The one cast: a kind is only ever given what its own parse returned.
template <class Spec>
const Spec& spec_of(const KindSpec& s, const std::string& task) {
  const auto* t = dynamic_cast<const KindSpecOf<Spec>*>(&s);
  if (!t) throw std::logic_error("job kind '" + task + "' was given a spec that another kind parsed");
  return t->spec();
}

// A JobKind whose parse returns a Spec and whose run, resolve and estimate take it.
template <class Spec>
JobKind typed_job_kind(std::string task, std::vector<std::string> scenes, std::vector<std::string> fields,
                       std::function<Spec(const nlohmann::json&, const CommonJobFields&)> parse,
                       std::function<void(const Spec&, JobContext&)> run,
                       std::function<nlohmann::json(const Spec&)> resolve,
                       std::function<JobCost(const Spec&)> estimate = {}) {
  auto typed = [task](const KindSpec& s) -> const Spec& { return spec_of<Spec>(s, task); };
  JobKind kind{std::move(task), std::move(scenes), std::move(fields), {}, {}, {}, {}, {}};
  kind.parse = [parse = std::move(parse)](const nlohmann::json& spec, const CommonJobFields& common) {
    return std::shared_ptr<const KindSpec>(std::make_shared<const KindSpecOf<Spec>>(parse(spec, common)));
  };
  kind.run = [typed, run = std::move(run)](const KindSpec& s, JobContext& ctx) { run(typed(s), ctx); };
  if (resolve) kind.resolve = [typed, resolve = std::move(resolve)](const KindSpec& s) { return resolve(typed(s)); };
  if (estimate) kind.estimate = [typed, estimate = std::move(estimate)](const KindSpec& s) { return estimate(typed(s)); };
  return kind;
}

// A typed kind (typed_job_kind) whose run() splits its jobs into work units computed by run_unit.
template <class Spec>
JobKind with_work_units(JobKind kind, std::function<void(const Spec&, const WorkUnit&, JobContext&)> run_unit) {
  kind.run_unit = [task = kind.task, run_unit = std::move(run_unit)](const KindSpec& s, const WorkUnit& unit,
                                                                    JobContext& ctx) { run_unit(spec_of<Spec>(s, task), unit, ctx); };
  return kind;
}

class JobKindRegistry {
 public:
  void add(JobKind kind);  // throws std::logic_error on a duplicate task
  const JobKind* find(const std::string& task) const;
  std::vector<std::string> tasks() const;

 private:
  std::map<std::string, JobKind> kinds_;
};

}  // namespace cyclopt::service
