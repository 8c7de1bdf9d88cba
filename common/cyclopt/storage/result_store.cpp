#include "cyclopt/storage/result_store.hpp"

#include "cyclopt/storage_read/results_schema.hpp"
#include "cyclopt/storage_read/schema_version.hpp"

#include <chrono>
#include <filesystem>
#include <limits>

#include <unistd.h>

namespace cyclopt::storage {

double unix_now() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

namespace {

// A server needs to write the file and, in WAL mode, to create FILE-wal and FILE-shm beside it:
// say so before SQLite's "unable to open database file" or "attempt to write a readonly database".
const std::string& writable_path(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path file(path);
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw StorageError("database '" + path + "': directory '" + dir.string() + "' does not exist");
  if (::access(dir.c_str(), W_OK) != 0)
    throw StorageError("database '" + path + "': directory '" + dir.string() +
                       "' is not writable (the server creates the database and its -wal/-shm files there)");
  if (fs::exists(file, ec) && ::access(file.c_str(), W_OK) != 0)
    throw StorageError("database '" + path + "': the file is read-only");
  return path;
}

// Records kSchemaVersion, after the migrations of a read-write open.
void record_schema_version(Connection& db) {
  Statement(db, "INSERT OR REPLACE INTO schema_info (key, value) VALUES ('version', ?)")
      .bind(1, std::string_view(std::to_string(kSchemaVersion)))
      .run();
}

// PRAGMA quick_check: a server must not write new jobs into a damaged file.
void check_integrity(Connection& db, const std::string& path) {
  std::string first;
  int problems = 0;
  try {
    Statement q(db, "PRAGMA quick_check(20)");
    while (q.step()) {
      const std::string row = q.text(0);
      if (row == "ok") continue;
      if (problems++ == 0) first = row;
    }
  } catch (const StorageError& e) {  // "file is not a database", "database disk image is malformed"
    first = e.what();
    problems = 1;
  }
  if (problems > 0)
    throw StorageError("database '" + path + "' is damaged (PRAGMA quick_check: " + first +
                       (problems > 1 ? ", and " + std::to_string(problems - 1) + " more" : "") +
                       "); refusing to start. Move it away (a new database is created) or recover it with "
                       "sqlite3 '" + path + "' .recover");
}

// Columns added while schema version 1 was deployed (migration to version 2), and those of versions
// 3 and 4: added to older files.
void add_missing_columns(Connection& db) {
  std::set<std::string> columns;
  {
    Statement q(db, "PRAGMA table_info(jobs)");
    while (q.step()) columns.insert(q.text(1));
  }
  if (!columns.count("sender")) db.exec("ALTER TABLE jobs ADD COLUMN sender TEXT NOT NULL DEFAULT ''");
  if (!columns.count("estimated_seconds")) db.exec("ALTER TABLE jobs ADD COLUMN estimated_seconds REAL");
  if (!columns.count("points_converged")) db.exec("ALTER TABLE jobs ADD COLUMN points_converged INTEGER");
  if (!columns.count("program_version")) db.exec("ALTER TABLE jobs ADD COLUMN program_version TEXT NOT NULL DEFAULT ''");
  if (!columns.count("seeds_json")) db.exec("ALTER TABLE jobs ADD COLUMN seeds_json TEXT NOT NULL DEFAULT '{}'");
  if (!columns.count("resolved_spec_json"))
    db.exec("ALTER TABLE jobs ADD COLUMN resolved_spec_json TEXT NOT NULL DEFAULT ''");
  if (!columns.count("isa_level")) db.exec("ALTER TABLE jobs ADD COLUMN isa_level TEXT NOT NULL DEFAULT ''");
  if (!columns.count("build_flags")) db.exec("ALTER TABLE jobs ADD COLUMN build_flags TEXT NOT NULL DEFAULT ''");
  for (const char* real : {"progress_percent", "eta_seconds", "best_objective", "progress_at"})
    if (!columns.count(real)) db.exec(std::string("ALTER TABLE jobs ADD COLUMN ") + real + " REAL");
  if (!columns.count("phase")) db.exec("ALTER TABLE jobs ADD COLUMN phase TEXT NOT NULL DEFAULT ''");
  std::set<std::string> solution_columns;
  {
    Statement q(db, "PRAGMA table_info(solutions)");
    while (q.step()) solution_columns.insert(q.text(1));
  }
  if (!solution_columns.count("required"))
    db.exec("ALTER TABLE solutions ADD COLUMN required INTEGER NOT NULL DEFAULT 1");
}

// Files made before the state 'incomplete' existed have a CHECK on jobs.state without it, which
// SQLite cannot alter: the table is rebuilt with the current list (the documented procedure:
// copy, drop, rename, with foreign keys off so the other tables' references stay).
void allow_every_job_state(Connection& db) {
  std::string sql;
  {
    Statement q(db, "SELECT sql FROM sqlite_master WHERE type = 'table' AND name = 'jobs'");
    if (q.step()) sql = q.text(0);
  }
  const std::size_t check = sql.find("'cancelled')");
  if (check == std::string::npos) return;  // the current list (or no CHECK at all)
  sql.replace(check, std::string("'cancelled')").size(), "'cancelled', 'incomplete')");
  db.exec("PRAGMA foreign_keys = OFF");
  {
    Transaction tx(db);
    db.exec("CREATE TABLE jobs_migrating " + sql.substr(sql.find('(')));
    db.exec("INSERT INTO jobs_migrating SELECT * FROM jobs");
    db.exec("DROP TABLE jobs");
    db.exec("ALTER TABLE jobs_migrating RENAME TO jobs");
    tx.commit();
  }
}

}  // namespace

ResultStore::ResultStore(const std::string& path) : ResultReader(writable_path(path), ReadWrite{}) {
  check_integrity(db_, path);
  check_schema_version(stored_schema_version(db_, path), path, false);
  db_.exec("PRAGMA journal_mode = WAL");
  db_.exec("PRAGMA synchronous = NORMAL");
  db_.exec(results_schema_sql());
  add_missing_columns(db_);
  allow_every_job_state(db_);
  db_.exec(results_schema_sql());  // the indexes of a rebuilt jobs table
  record_schema_version(db_);        // a version-1 file is now migrated
  db_.exec("PRAGMA foreign_keys = ON");
}

SubmitOutcome ResultStore::submit(const Submission& sub, const SenderQuota& quota) {
  std::lock_guard lock(mutex_);
  Transaction tx(db_);
  SubmitOutcome out;
  {
    Statement find(db_, "SELECT id, spec_json, state FROM jobs WHERE request_id = ?");
    if (find.bind(1, sub.request_id).step()) {
      out.job_id = find.int64(0);
      out.duplicate = true;
      out.spec_differs = find.text(1) != sub.spec_json;
      out.state = job_state_from_string(find.text(2)).value_or(JobState::failed);
      return out;
    }
  }
  {
    Statement queued(db_, "SELECT count(*), total(estimated_seconds) FROM jobs WHERE state = 'queued' AND sender = ?");
    queued.bind(1, sub.sender).step();
    out.queued_jobs = static_cast<int>(queued.int64(0));
    out.queued_seconds = queued.real(1);
  }
  if (out.queued_jobs + 1 > quota.max_queued_jobs || out.queued_seconds + sub.estimated_seconds > quota.max_queued_seconds) {
    out.over_quota = true;
    return out;
  }
  Statement ins(db_,
                "INSERT INTO jobs (request_id, scene, task, spec_json, submitted_at, sender, estimated_seconds, "
                "program_version, seeds_json, resolved_spec_json, isa_level, build_flags) "
                "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  ins.bind(1, sub.request_id)
      .bind(2, sub.scene)
      .bind(3, sub.task)
      .bind(4, sub.spec_json)
      .bind(5, unix_now())
      .bind(6, sub.sender)
      .bind(7, sub.estimated_seconds)
      .bind(8, sub.program_version)
      .bind(9, sub.seeds_json)
      .bind(10, sub.resolved_spec_json)
      .bind(11, sub.isa_level)
      .bind(12, sub.build_flags)
      .run();
  out.job_id = db_.last_insert_rowid();
  add_event_locked(out.job_id, "submitted", "request " + sub.request_id);
  tx.commit();
  return out;
}

SubmitOutcome ResultStore::submit(const std::string& request_id, const std::string& scene, const std::string& task,
                                  const std::string& spec_json) {
  return submit({request_id, scene, task, spec_json, "", 0.0, "", "{}", "", "", ""},
                {std::numeric_limits<int>::max(), std::numeric_limits<double>::infinity()});
}

std::optional<JobRecord> ResultStore::claim_next() {
  std::lock_guard lock(mutex_);
  Transaction tx(db_);
  std::int64_t id = 0;
  {
    Statement pick(db_, "SELECT id FROM jobs WHERE state = 'queued' ORDER BY id LIMIT 1");
    if (!pick.step()) return std::nullopt;
    id = pick.int64(0);
  }
  Statement upd(db_, "UPDATE jobs SET state = 'running', attempts = attempts + 1, started_at = ? WHERE id = ?");
  upd.bind(1, unix_now()).bind(2, id).run();
  add_event_locked(id, "started", "");
  std::optional<JobRecord> r = job_locked(id);
  tx.commit();
  return r;
}

RecoverySummary ResultStore::recover_interrupted(const std::set<std::int64_t>& live, const std::string& why) {
  std::lock_guard lock(mutex_);
  Transaction tx(db_);
  RecoverySummary s;
  std::vector<std::pair<std::int64_t, bool>> running;
  {
    Statement q(db_, "SELECT id, cancel_requested FROM jobs WHERE state = 'running'");
    while (q.step()) running.emplace_back(q.int64(0), q.int64(1) != 0);
  }
  for (const auto& [id, cancel] : running) {
    if (live.count(id)) continue;
    if (cancel)
      Statement(db_, "UPDATE jobs SET state = 'cancelled', finished_at = ? WHERE id = ?").bind(1, unix_now()).bind(2, id).run();
    else
      Statement(db_, "UPDATE jobs SET state = 'queued', started_at = NULL WHERE id = ?").bind(1, id).run();
    add_event_locked(id, cancel ? "cancelled" : "requeued", why);
    ++(cancel ? s.cancelled : s.requeued);
  }
  tx.commit();
  return s;
}

void ResultStore::return_to_queue(std::int64_t job_id, double run_seconds, double publish_seconds,
                                  const std::string& why) {
  std::lock_guard lock(mutex_);
  Transaction tx(db_);
  Statement upd(db_,
                "UPDATE jobs SET state = 'queued', started_at = NULL, run_seconds = run_seconds + ?, "
                "publish_seconds = publish_seconds + ? WHERE id = ?");
  upd.bind(1, run_seconds).bind(2, publish_seconds).bind(3, job_id).run();
  tx.commit();  // the state first, in its own transaction: an UPDATE in place needs no new page
  add_event_if_room_locked(job_id, "interrupted", why);
}

void ResultStore::add_run_seconds(std::int64_t job_id, double seconds) {
  std::lock_guard lock(mutex_);
  Statement(db_, "UPDATE jobs SET run_seconds = run_seconds + ? WHERE id = ?").bind(1, seconds).bind(2, job_id).run();
}

void ResultStore::finish(std::int64_t job_id, JobState final_state, const std::string& error, double run_seconds,
                         double publish_seconds, std::optional<int> points_converged) {
  std::lock_guard lock(mutex_);
  Transaction tx(db_);
  Statement upd(db_,
                "UPDATE jobs SET state = ?, finished_at = ?, error = ?, run_seconds = run_seconds + ?, "
                "publish_seconds = publish_seconds + ?, points_converged = ? WHERE id = ?");
  upd.bind(1, to_string(final_state)).bind(2, unix_now());
  if (error.empty())
    upd.bind(3, std::nullopt);
  else
    upd.bind(3, error);
  upd.bind(4, run_seconds).bind(5, publish_seconds);
  if (points_converged)
    upd.bind(6, std::int64_t{*points_converged});
  else
    upd.bind(6, std::nullopt);
  upd.bind(7, job_id).run();
  tx.commit();  // the state first (see return_to_queue)
  add_event_if_room_locked(job_id, std::string(to_string(final_state)), error);
}

CancelOutcome ResultStore::cancel(std::int64_t job_id) {
  std::lock_guard lock(mutex_);
  Transaction tx(db_);
  JobState state;
  {
    Statement q(db_, "SELECT state FROM jobs WHERE id = ?");
    if (!q.bind(1, job_id).step()) return CancelOutcome::not_found;
    state = job_state_from_string(q.text(0)).value_or(JobState::failed);
  }
  if (is_final(state)) return CancelOutcome::already_final;
  CancelOutcome out;
  if (state == JobState::queued) {
    Statement upd(db_, "UPDATE jobs SET state = 'cancelled', cancel_requested = 1, finished_at = ? WHERE id = ?");
    upd.bind(1, unix_now()).bind(2, job_id).run();
    add_event_locked(job_id, "cancelled", "cancelled while queued");
    out = CancelOutcome::cancelled;
  } else {
    Statement upd(db_, "UPDATE jobs SET cancel_requested = 1 WHERE id = ?");
    upd.bind(1, job_id).run();
    add_event_locked(job_id, "cancel_requested", "");
    out = CancelOutcome::cancel_requested;
  }
  tx.commit();
  return out;
}

void ResultStore::set_points_total(std::int64_t job_id, int total) {
  std::lock_guard lock(mutex_);
  Statement(db_, "UPDATE jobs SET points_total = ? WHERE id = ?").bind(1, std::int64_t{total}).bind(2, job_id).run();
}

void ResultStore::set_progress(std::int64_t job_id, const JobProgressRecord& p) {
  std::lock_guard lock(mutex_);
  Statement(db_, "UPDATE jobs SET progress_percent = ?, phase = ?, eta_seconds = ?, best_objective = ?, progress_at = ? "
                 "WHERE id = ?")
      .bind(1, p.percent)
      .bind(2, p.phase)
      .bind(3, p.eta_seconds)
      .bind(4, p.best_objective)
      .bind(5, p.at)
      .bind(6, job_id)
      .run();
}

void ResultStore::add_curve(std::int64_t job_id, int curve_index, const std::string& name,
                            const std::string& parameter_name) {
  std::lock_guard lock(mutex_);
  Statement(db_, "INSERT OR IGNORE INTO curves (job_id, curve_index, name, parameter_name) VALUES (?, ?, ?, ?)")
      .bind(1, job_id)
      .bind(2, std::int64_t{curve_index})
      .bind(3, name)
      .bind(4, parameter_name)
      .run();
}

bool ResultStore::store_point(std::int64_t job_id, const SolutionPoint& p) {
  std::lock_guard lock(mutex_);
  Transaction tx(db_);
  Statement ins(db_,
                "INSERT INTO solutions (job_id, curve_index, point_index, parameter, objective, constraint_violation, "
                "iterations, status, values_json, solved_at, required) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?) "
                "ON CONFLICT (job_id, curve_index, point_index) DO NOTHING");
  ins.bind(1, job_id)
      .bind(2, std::int64_t{p.key.curve_index})
      .bind(3, std::int64_t{p.key.point_index})
      .bind(4, p.parameter)
      .bind(5, p.objective)
      .bind(6, p.constraint_violation)
      .bind(7, std::int64_t{p.iterations})
      .bind(8, p.status)
      .bind(9, p.values().dump())
      .bind(10, unix_now())
      .bind(11, std::int64_t{p.required})
      .run();
  if (db_.changes() == 0) return false;
  if (p.trajectory()) {
    Statement tr(db_, "INSERT INTO trajectories (solution_id, format, data) VALUES (?, 'json', ?)");
    tr.bind(1, db_.last_insert_rowid()).bind_blob(2, p.trajectory()->dump()).run();
  }
  tx.commit();
  return true;
}

void ResultStore::store_checkpoint(std::int64_t job_id, const std::string& key, const std::string& value) {
  std::lock_guard lock(mutex_);
  Statement ins(db_, "INSERT OR REPLACE INTO checkpoints (job_id, key, value) VALUES (?, ?, ?)");
  ins.bind(1, job_id).bind(2, key).bind(3, value).run();
}

void ResultStore::add_event(std::int64_t job_id, const std::string& kind, const std::string& message) {
  std::lock_guard lock(mutex_);
  add_event_locked(job_id, kind, message);
}

void ResultStore::add_event_locked(std::int64_t job_id, const std::string& kind, const std::string& message) {
  Statement(db_, "INSERT INTO events (job_id, at, kind, message) VALUES (?, ?, ?, ?)")
      .bind(1, job_id)
      .bind(2, unix_now())
      .bind(3, kind)
      .bind(4, message)
      .run();
}

void ResultStore::add_event_if_room_locked(std::int64_t job_id, const std::string& kind, const std::string& message) {
  try {
    Transaction tx(db_);
    add_event_locked(job_id, kind, message);
    tx.commit();
  } catch (const StorageError&) {  // SQLITE_FULL (which may roll back the whole transaction): drop the log line
  }
}

}  // namespace cyclopt::storage
