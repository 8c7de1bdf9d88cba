#pragma once
// A results database (schema: results_schema.hpp) opened for reading: the jobs, a job's stored
// points, its checkpoints. What the clients (a local `cyclopt query --database`), cyclopt-web and
// the Python package use beside a running server, which holds the one writer
// (storage/result_store.hpp: a ResultStore is a ResultReader that also writes). Thread-safe: one
// connection guarded by a mutex.

#include "cyclopt/storage_read/job_record.hpp"
#include "cyclopt/storage_read/solution_point.hpp"
#include "cyclopt/storage_read/sqlite_handle.hpp"

#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace cyclopt::storage {

// What the outcome of a job is judged by (storage/job_outcome.hpp): a stored required point's status.
struct RequiredPoint {
  PointKey key;
  double parameter;
  std::string status;
  std::string parameter_name;  // of its curve ("" if the curve was not declared)
};

class ResultReader {
 public:
  // Opens `path` read-only (SQLite's query_only): throws StorageError when it cannot be read or
  // holds a results schema this build cannot read without migrating it (schema_version.hpp).
  explicit ResultReader(const std::string& path);

  std::optional<JobRecord> job(std::int64_t job_id);
  // sender: only the jobs it submitted (storage/result_store.hpp Submission::sender).
  std::vector<JobRecord> jobs(std::optional<JobState> state, int offset, int limit,
                              const std::optional<std::string>& sender = std::nullopt);
  int count_jobs(std::optional<JobState> state, const std::optional<std::string>& sender = std::nullopt);
  std::set<PointKey> stored_points(std::int64_t job_id);
  // The values_json of a stored point; nullopt if the job has no such point.
  std::optional<std::string> point_values(std::int64_t job_id, PointKey key);
  // The stored points with required = 1 (solution_point.hpp), by curve and point index.
  std::vector<RequiredPoint> required_points(std::int64_t job_id);
  std::map<std::string, std::string> checkpoints(std::int64_t job_id);

  Connection& connection() { return db_; }  // for result_queries.hpp; lock with mutex()
  std::mutex& mutex() { return mutex_; }

 protected:
  struct ReadWrite {};
  // Opens `path` for reading and writing: the writer checks and migrates the file itself.
  ResultReader(const std::string& path, ReadWrite);
  std::optional<JobRecord> job_locked(std::int64_t job_id);  // job() with mutex() held by the caller

  Connection db_;
  std::mutex mutex_;
};

}  // namespace cyclopt::storage
