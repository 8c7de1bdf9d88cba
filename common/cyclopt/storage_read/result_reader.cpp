#include "cyclopt/storage_read/result_reader.hpp"

#include "cyclopt/storage_read/schema_version.hpp"

#include <limits>

namespace cyclopt::storage {

namespace {

constexpr const char* kJobColumns =
    "j.id, j.request_id, j.scene, j.task, j.spec_json, j.state, j.cancel_requested, j.attempts, j.submitted_at, "
    "j.started_at, j.finished_at, j.points_total, "
    "(SELECT count(*) FROM solutions s WHERE s.job_id = j.id), j.run_seconds, j.publish_seconds, j.error, "
    "j.points_converged, j.program_version, j.seeds_json, j.resolved_spec_json, j.isa_level, j.build_flags, "
    "j.progress_percent, j.phase, j.eta_seconds, j.best_objective, j.progress_at";

std::optional<double> optional_real(const Statement& s, int col) {
  return s.is_null(col) ? std::nullopt : std::optional<double>(s.real(col));
}

JobRecord read_job(const Statement& s) {
  JobRecord r;
  r.id = s.int64(0);
  r.request_id = s.text(1);
  r.scene = s.text(2);
  r.task = s.text(3);
  r.spec_json = s.text(4);
  r.state = job_state_from_string(s.text(5)).value_or(JobState::failed);
  r.cancel_requested = s.int64(6) != 0;
  r.attempts = static_cast<int>(s.int64(7));
  r.submitted_at = s.real(8);
  r.started_at = optional_real(s, 9);
  r.finished_at = optional_real(s, 10);
  if (!s.is_null(11)) r.points_total = static_cast<int>(s.int64(11));
  r.points_stored = static_cast<int>(s.int64(12));
  r.run_seconds = s.real(13);
  r.publish_seconds = s.real(14);
  r.error = s.text(15);
  if (!s.is_null(16)) r.points_converged = static_cast<int>(s.int64(16));
  r.program_version = s.text(17);
  r.seeds_json = s.text(18);
  r.resolved_spec_json = s.text(19);
  r.isa_level = s.text(20);
  r.build_flags = s.text(21);
  r.progress = {optional_real(s, 22), s.text(23), optional_real(s, 24), optional_real(s, 25), optional_real(s, 26)};
  return r;
}

}  // namespace

ResultReader::ResultReader(const std::string& path) : db_(path, true) {
  db_.exec("PRAGMA query_only = ON");
  check_schema_version(stored_schema_version(db_, path), path, true);
}

ResultReader::ResultReader(const std::string& path, ReadWrite) : db_(path, false) {}

std::optional<JobRecord> ResultReader::job(std::int64_t job_id) {
  std::lock_guard lock(mutex_);
  return job_locked(job_id);
}

std::optional<JobRecord> ResultReader::job_locked(std::int64_t job_id) {
  Statement q(db_, std::string("SELECT ") + kJobColumns + " FROM jobs j WHERE j.id = ?");
  if (!q.bind(1, job_id).step()) return std::nullopt;
  return read_job(q);
}

std::vector<JobRecord> ResultReader::jobs(std::optional<JobState> state, int offset, int limit,
                                         const std::optional<std::string>& sender) {
  std::lock_guard lock(mutex_);
  Statement q(db_, std::string("SELECT ") + kJobColumns +
                       " FROM jobs j WHERE (?1 IS NULL OR j.state = ?1) AND (?4 IS NULL OR j.sender = ?4) "
                       "ORDER BY j.id LIMIT ?2 OFFSET ?3");
  if (state)
    q.bind(1, to_string(*state));
  else
    q.bind(1, std::nullopt);
  q.bind(2, std::int64_t{limit}).bind(3, std::int64_t{offset});
  if (sender)
    q.bind(4, *sender);
  else
    q.bind(4, std::nullopt);
  std::vector<JobRecord> out;
  while (q.step()) out.push_back(read_job(q));
  return out;
}

int ResultReader::count_jobs(std::optional<JobState> state, const std::optional<std::string>& sender) {
  std::lock_guard lock(mutex_);
  Statement q(db_, "SELECT count(*) FROM jobs WHERE (?1 IS NULL OR state = ?1) AND (?2 IS NULL OR sender = ?2)");
  if (state)
    q.bind(1, to_string(*state));
  else
    q.bind(1, std::nullopt);
  if (sender)
    q.bind(2, *sender);
  else
    q.bind(2, std::nullopt);
  q.step();
  return static_cast<int>(q.int64(0));
}

std::set<PointKey> ResultReader::stored_points(std::int64_t job_id) {
  std::lock_guard lock(mutex_);
  std::set<PointKey> keys;
  Statement q(db_, "SELECT curve_index, point_index FROM solutions WHERE job_id = ?");
  q.bind(1, job_id);
  while (q.step()) keys.insert({static_cast<int>(q.int64(0)), static_cast<int>(q.int64(1))});
  return keys;
}

std::optional<std::string> ResultReader::point_values(std::int64_t job_id, PointKey key) {
  std::lock_guard lock(mutex_);
  Statement q(db_, "SELECT values_json FROM solutions WHERE job_id = ? AND curve_index = ? AND point_index = ?");
  q.bind(1, job_id).bind(2, std::int64_t{key.curve_index}).bind(3, std::int64_t{key.point_index});
  if (!q.step()) return std::nullopt;
  return q.text(0);
}

std::vector<RequiredPoint> ResultReader::required_points(std::int64_t job_id) {
  std::lock_guard lock(mutex_);
  std::vector<RequiredPoint> points;
  Statement q(db_,
              "SELECT s.curve_index, s.point_index, s.parameter, s.status, coalesce(c.parameter_name, '') "
              "FROM solutions s LEFT JOIN curves c ON c.job_id = s.job_id AND c.curve_index = s.curve_index "
              "WHERE s.job_id = ? AND s.required = 1 ORDER BY s.curve_index, s.point_index");
  q.bind(1, job_id);
  while (q.step())
    points.push_back({{static_cast<int>(q.int64(0)), static_cast<int>(q.int64(1))},
                      q.is_null(2) ? std::numeric_limits<double>::quiet_NaN() : q.real(2), q.text(3), q.text(4)});
  return points;
}

std::map<std::string, std::string> ResultReader::checkpoints(std::int64_t job_id) {
  std::lock_guard lock(mutex_);
  std::map<std::string, std::string> out;
  Statement q(db_, "SELECT key, value FROM checkpoints WHERE job_id = ?");
  q.bind(1, job_id);
  while (q.step()) out.emplace(q.text(0), q.text(1));
  return out;
}

}  // namespace cyclopt::storage
