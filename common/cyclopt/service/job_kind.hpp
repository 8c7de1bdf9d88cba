#pragma once
// Pluggable job kinds. A job spec's "task" selects a JobKind from the registry; the server
// validates a submission with validate() before it is queued and calls run() on a worker.
//
// Adding a kind (e.g. the walker's speed sweep) takes ~20 lines:
//
//   // walker_sweep_kind.hpp
//   service::JobKind walker_sweep_kind();
//
//   // walker_sweep_kind.cpp
//   service::JobKind walker_sweep_kind() {
//     return {"sweep", {"walker"}, {"foot", "speeds"},
//       [](const nlohmann::json& spec) {            // throw SpecError{"speeds", "..."} on bad input
//         io::foot_spec_from_json(spec.at("foot"), "foot");
//         service::parse_value_range(spec.at("speeds"), "speeds", 0.05, 5.0);
//       },
//       [](const nlohmann::json& spec, service::JobContext& ctx) {
//         const auto speeds = service::parse_value_range(spec["speeds"], "speeds", 0.05, 5.0);
//         ctx.announce(int(speeds.size()));
//         ctx.add_curve(0, "speed sweep", "speed");
//         const auto done = ctx.already_stored_points();
//         for (int i = 0; i < int(speeds.size()); ++i) {
//           if (done.count({0, i})) continue;                    // resumed job: already solved
//           if (ctx.stop_reason() != service::StopReason::none) return;
//           // ... solve with service::solver_options_from_spec(spec), whose on_iteration calls
//           //     ctx.report_progress(...), ctx.count_iterations(1) and returns
//           //     ctx.stop_reason() == StopReason::none ...
//           storage::SolutionPoint p;
//           p.key = {0, i};
//           p.parameter = speeds[i];
//           p.objective = summary.objective;              // + values, status, trajectory
//           ctx.store_point(p);
//         }
//       }};
//   }
//
// and one line in builtin_job_kinds.cpp: registry.add(walker_sweep_kind());
//
// Contract for estimate(): it is given a spec that passed validate(); kinds whose cost grows with
// their spec (grid size, starts, speeds) provide it.
//
// Contract for run(): it is given a spec that passed validate(); it returns normally when all
// points are stored or when stop_reason() became non-none (the server then decides the job's
// state); it throws (any std::exception) only when the job failed — the message is stored.
// It must be re-entrant (several workers run jobs of the same kind) and must not keep state
// between calls: everything a resumed job needs is in the store.

#include "cyclopt/service/job_context.hpp"
#include "cyclopt/service/job_cost.hpp"

#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace cyclopt::service {

struct JobKind {
  std::string task;                       // the spec's "task"
  std::vector<std::string> scenes;        // admissible "scene" values
  std::vector<std::string> fields;        // top-level spec keys the kind reads (besides the common ones)
  std::function<void(const nlohmann::json& spec)> validate;        // throws SpecError
  std::function<void(const nlohmann::json& spec, JobContext& ctx)> run;
  // Expected time and memory of a valid spec, checked against the server's limits before the job
  // is queued (job_cost.hpp); empty: the kind's jobs are cheap (seconds, little memory).
  std::function<JobCost(const nlohmann::json& spec)> estimate;
};

class JobKindRegistry {
 public:
  void add(JobKind kind);  // throws std::logic_error on a duplicate task
  const JobKind* find(const std::string& task) const;
  std::vector<std::string> tasks() const;

 private:
  std::map<std::string, JobKind> kinds_;
};

}  // namespace cyclopt::service
