#pragma once
// The results database and durable job queue (schema: storage_read/results_schema.hpp), opened
// for writing: the server's one writer. It reads what a ResultReader reads
// (storage_read/result_reader.hpp; the clients open the file with that while a server writes).
// Thread-safe: one connection guarded by a mutex; every write is its own transaction, so a point
// is durable the moment store_point() returns.

#include "cyclopt/storage_read/result_reader.hpp"

#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace cyclopt::storage {

// What a submission adds to the queue. sender identifies the submitter for the queue quota (the
// authenticated key, "host <address>" for an unauthenticated client whose address the server
// knows, else "", one quota shared by all such clients).
struct Submission {
  std::string request_id;
  std::string scene;
  std::string task;
  std::string spec_json;
  std::string sender;
  double estimated_seconds = 0.0;  // the job's cost estimate (service/job_cost.hpp)
  // What reproduces the job (results_schema.hpp): the accepting build's git revision, the random
  // seeds by field ({"multistart.seed": 1}), the spec with its defaults filled in, and the build's
  // instruction-set level and compiler flags.
  std::string program_version;
  std::string seeds_json = "{}";
  std::string resolved_spec_json;
  std::string isa_level;
  std::string build_flags;
};

// Per-sender limits on queued (not yet running) jobs; checked in the submission's transaction.
struct SenderQuota {
  int max_queued_jobs = 100;
  double max_queued_seconds = 7 * 86400.0;  // sum of their estimated_seconds
};

struct SubmitOutcome {
  std::int64_t job_id = 0;
  bool duplicate = false;     // request id known before: nothing was added
  bool spec_differs = false;  // ... and with a different spec
  bool over_quota = false;    // not added: the sender's queued jobs would exceed the quota
  int queued_jobs = 0;        // the sender's queued jobs before this submission
  double queued_seconds = 0.0;  // ... and their estimated seconds
  JobState state = JobState::queued;
};

enum class CancelOutcome { not_found, already_final, cancelled, cancel_requested };

// Counts of what recover_interrupted() did at start-up.
struct RecoverySummary {
  int requeued = 0;
  int cancelled = 0;
};

class ResultStore : public ResultReader {
 public:
  // Creates the file if need be, checks its integrity and migrates an older schema; throws
  // StorageError naming what is wrong (a directory that does not exist or is not writable).
  explicit ResultStore(const std::string& path);

  // Queue.
  SubmitOutcome submit(const Submission& s, const SenderQuota& quota);
  // Without a sender, estimate or quota (tests, tools filling a database).
  SubmitOutcome submit(const std::string& request_id, const std::string& scene, const std::string& task,
                       const std::string& spec_json);
  std::optional<JobRecord> claim_next();  // oldest queued job -> running (attempts + 1)
  // running -> queued, or cancelled if cancel was asked, except the jobs in `live` (those a worker
  // of this server runs); `why` goes into each job's event.
  RecoverySummary recover_interrupted(const std::set<std::int64_t>& live = {},
                                      const std::string& why = "interrupted while running (server restart)");
  // run_seconds, publish_seconds: what this attempt adds to the job's totals (beyond what
  // add_run_seconds() already recorded). Both commit the state change before its event, and the
  // event only if the file has room for it, so a job's state can still be recorded on a full disk.
  void return_to_queue(std::int64_t job_id, double run_seconds, double publish_seconds, const std::string& why);
  // points_converged: the job's required points that converged (job_outcome.hpp), if judged.
  void finish(std::int64_t job_id, JobState final_state, const std::string& error, double run_seconds,
              double publish_seconds, std::optional<int> points_converged = std::nullopt);
  // Checkpoints a running attempt's time, so it counts after a kill -9 too.
  void add_run_seconds(std::int64_t job_id, double seconds);
  CancelOutcome cancel(std::int64_t job_id);

  // Results.
  void set_points_total(std::int64_t job_id, int total);
  // The job's last progress (results_schema.hpp), replacing the one before.
  void set_progress(std::int64_t job_id, const JobProgressRecord& progress);
  void add_curve(std::int64_t job_id, int curve_index, const std::string& name, const std::string& parameter_name);
  bool store_point(std::int64_t job_id, const SolutionPoint& p);  // false: point was already stored
  void store_checkpoint(std::int64_t job_id, const std::string& key, const std::string& value);  // replaces
  void add_event(std::int64_t job_id, const std::string& kind, const std::string& message);

 private:
  void add_event_locked(std::int64_t job_id, const std::string& kind, const std::string& message);
  void add_event_if_room_locked(std::int64_t job_id, const std::string& kind, const std::string& message);
};

double unix_now();

}  // namespace cyclopt::storage
