#pragma once
// The results database and durable job queue (schema: results_schema.hpp). Thread-safe: one
// connection guarded by a mutex; every write is its own transaction, so a point is durable the
// moment store_point() returns. Open read-only for local queries while a server writes.

#include "cyclopt/storage/job_record.hpp"
#include "cyclopt/storage/solution_point.hpp"
#include "cyclopt/storage/sqlite_handle.hpp"

#include <cstdint>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace cyclopt::storage {

enum class OpenMode { read_write, read_only };

struct SubmitOutcome {
  std::int64_t job_id = 0;
  bool duplicate = false;     // request id known before: nothing was added
  bool spec_differs = false;  // ... and with a different spec
  JobState state = JobState::queued;
};

enum class CancelOutcome { not_found, already_final, cancelled, cancel_requested };

// Counts of what recover_interrupted() did at start-up.
struct RecoverySummary {
  int requeued = 0;
  int cancelled = 0;
};

class ResultStore {
 public:
  ResultStore(const std::string& path, OpenMode mode = OpenMode::read_write);

  // Queue.
  SubmitOutcome submit(const std::string& request_id, const std::string& scene, const std::string& task,
                       const std::string& spec_json);
  std::optional<JobRecord> claim_next();  // oldest queued job -> running (attempts + 1)
  RecoverySummary recover_interrupted();  // running -> queued, or cancelled if cancel was asked
  void return_to_queue(std::int64_t job_id, double run_seconds, double publish_seconds, const std::string& why);
  void finish(std::int64_t job_id, JobState final_state, const std::string& error, double run_seconds,
              double publish_seconds);
  CancelOutcome cancel(std::int64_t job_id);

  // Results.
  void set_points_total(std::int64_t job_id, int total);
  void add_curve(std::int64_t job_id, int curve_index, const std::string& name, const std::string& parameter_name);
  bool store_point(std::int64_t job_id, const SolutionPoint& p);  // false: point was already stored
  std::set<PointKey> stored_points(std::int64_t job_id);
  void add_event(std::int64_t job_id, const std::string& kind, const std::string& message);

  // Reads.
  std::optional<JobRecord> job(std::int64_t job_id);
  std::vector<JobRecord> jobs(std::optional<JobState> state, int offset, int limit);
  int count_jobs(std::optional<JobState> state);
  Connection& connection() { return db_; }  // for result_queries.hpp; lock with mutex()
  std::mutex& mutex() { return mutex_; }

 private:
  void add_event_locked(std::int64_t job_id, const std::string& kind, const std::string& message);
  Connection db_;
  std::mutex mutex_;
};

double unix_now();

}  // namespace cyclopt::storage
