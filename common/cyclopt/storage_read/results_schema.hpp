#pragma once
// The SQLite schema of the results database (version 5, kSchemaVersion). The database runs in WAL mode with
// synchronous=NORMAL and foreign keys on: every committed point survives a kill -9 of the server.
//
//   jobs          one row per accepted submission; also the durable queue.
//     id            INTEGER PRIMARY KEY   job id shown to users
//     request_id    TEXT UNIQUE NOT NULL  client-generated; resubmitting it never adds a job
//     scene, task   TEXT                  copied from the spec ("walker", "foot_sweep", ...)
//     spec_json     TEXT NOT NULL         the spec as submitted (validated)
//     state         TEXT                  queued | running | done | incomplete | failed | cancelled
//                                         (job_state.hpp; files made before 'incomplete' existed
//                                         are migrated when a server opens them)
//     cancel_requested INTEGER 0/1        set by cancel while running; honoured after a restart
//     attempts      INTEGER               how often a worker started it (>1 after a resume)
//     submitted_at, started_at, finished_at  REAL, Unix seconds (UTC)
//     points_total  INTEGER               announced by the job kind (NULL until known)
//     run_seconds, publish_seconds  REAL  wall time inside the job kind / CPU time its worker
//                                         spent publishing progress, summed over attempts
//                                         (run_seconds is checkpointed every 5 s and with every
//                                         point, so a kill -9 loses at most that much)
//     error         TEXT                  why a job failed, or which points an incomplete job lacks
//     points_converged INTEGER            required points that converged (NULL until the job ends)
//     sender        TEXT                  who submitted it, for the queue quota ("" anonymous)
//     estimated_seconds REAL              the cost estimate at submission (service/job_cost.hpp)
//     program_version TEXT                the git revision of the server that accepted it
//                                         (cli/version.hpp; '' for jobs stored before version 3)
//     seeds_json    TEXT                  the random seeds the job uses, by field of the resolved
//                                         spec: {"multistart.seed": 1} ('{}': none)
//     resolved_spec_json TEXT             the spec with every default filled in
//                                         (service/resolved_spec.hpp; '' before version 3)
//     isa_level     TEXT                  the instruction-set level of that build (CMake
//                                         CYCLOPT_ARCH, "x86-64-v3" by default): a job's results
//                                         are bitwise reproducible by a build of the same level
//     build_flags   TEXT                  the compiler and its code-generation flags
//                                         ('' for both before version 4)
//     progress_percent, phase, eta_seconds, best_objective, progress_at  the job's last recorded
//                                         progress (service/progress_meter.hpp), written at every
//                                         phase change, every few seconds and when the job ends:
//                                         percent 0..100 (100 only for a finished job), the phase
//                                         text, the ETA in s, the best objective so far (NULL:
//                                         unknown), Unix seconds of the record (NULLs before version 5)
//   events        append-only log: (id, job_id, at, kind, message); kinds: submitted, started,
//                 requeued, cancel_requested, done, failed, cancelled, interrupted, phase (the
//                 running job entered a phase: message "PHASE | 42% | ETA 3:05 | best 0.0226")
//   curves        (id, job_id, curve_index, name, parameter_name), UNIQUE(job_id, curve_index):
//                 a branch of a continuation, or the single curve of a sweep
//   solutions     one row per solved point, UNIQUE(job_id, curve_index, point_index) so a resumed
//                 job can never store a point twice:
//                 (id, job_id, curve_index, point_index, parameter, objective,
//                  constraint_violation, iterations, status, values_json, solved_at, required)
//                 required 0/1: whether the point counts for the job's outcome (solution_point.hpp)
//   trajectories  (id, solution_id UNIQUE -> solutions.id, format, data BLOB): the time series or
//                 profile belonging to a solution ("json" = UTF-8 JSON document in the blob)
//   checkpoints   (job_id, key, value), PRIMARY KEY(job_id, key): intermediate results of a job
//                 that a resumed attempt reuses (a sweep's finished solves and continuation runs,
//                 service/sweep_checkpoints.hpp); not results. Added after version 1 was
//                 deployed; created in place in older files.
//   schema_info   (key, value): "version" = kSchemaVersion, checked on every open
//                 (schema_version.hpp): older files are migrated by a server, newer ones refused
//
// Versions: 1 the first deployed layout, which grew in place while deployed (jobs.sender,
// estimated_seconds, points_converged, solutions.required, checkpoints, state 'incomplete');
// 2 the same tables, with values_json and the "json" trajectories holding the records of the
// result contract (records/: gait, solver, walker point, foot comparison) and the version checked
// on open; 3 adds jobs.program_version, seeds_json and resolved_spec_json (reproducible results); 4
// adds jobs.isa_level and build_flags; 5 the jobs' last progress (progress_percent .. progress_at). Migrating adds the columns an older file lacks and records
// the current version.
//
// Example queries: docs/results.md, "The database".

#include <string_view>

namespace cyclopt::storage {

inline constexpr int kSchemaVersion = 5;

// DDL creating every table and index (IF NOT EXISTS, so it is idempotent).
std::string_view results_schema_sql();

}  // namespace cyclopt::storage
