#include "cyclopt/storage/result_store.hpp"

#include "cyclopt/storage/results_schema.hpp"

#include <chrono>

namespace cyclopt::storage {

double unix_now() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

namespace {

constexpr const char* kJobColumns =
    "j.id, j.request_id, j.scene, j.task, j.spec_json, j.state, j.cancel_requested, j.attempts, j.submitted_at, "
    "j.started_at, j.finished_at, j.points_total, "
    "(SELECT count(*) FROM solutions s WHERE s.job_id = j.id), j.run_seconds, j.publish_seconds, j.error";

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
  return r;
}

}  // namespace

ResultStore::ResultStore(const std::string& path, OpenMode mode) : db_(path, mode == OpenMode::read_only) {
  if (mode == OpenMode::read_only) {
    db_.exec("PRAGMA query_only = ON");
    return;
  }
  db_.exec("PRAGMA journal_mode = WAL");
  db_.exec("PRAGMA synchronous = NORMAL");
  db_.exec("PRAGMA foreign_keys = ON");
  db_.exec(results_schema_sql());
}

SubmitOutcome ResultStore::submit(const std::string& request_id, const std::string& scene, const std::string& task,
                                  const std::string& spec_json) {
  std::lock_guard lock(mutex_);
  Transaction tx(db_);
  SubmitOutcome out;
  {
    Statement find(db_, "SELECT id, spec_json, state FROM jobs WHERE request_id = ?");
    if (find.bind(1, request_id).step()) {
      out.job_id = find.int64(0);
      out.duplicate = true;
      out.spec_differs = find.text(1) != spec_json;
      out.state = job_state_from_string(find.text(2)).value_or(JobState::failed);
      return out;
    }
  }
  Statement ins(db_, "INSERT INTO jobs (request_id, scene, task, spec_json, submitted_at) VALUES (?, ?, ?, ?, ?)");
  ins.bind(1, request_id).bind(2, scene).bind(3, task).bind(4, spec_json).bind(5, unix_now()).run();
  out.job_id = db_.last_insert_rowid();
  add_event_locked(out.job_id, "submitted", "request " + request_id);
  tx.commit();
  return out;
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
  Statement get(db_, std::string("SELECT ") + kJobColumns + " FROM jobs j WHERE j.id = ?");
  get.bind(1, id).step();
  JobRecord r = read_job(get);
  tx.commit();
  return r;
}

RecoverySummary ResultStore::recover_interrupted() {
  std::lock_guard lock(mutex_);
  Transaction tx(db_);
  RecoverySummary s;
  std::vector<std::pair<std::int64_t, bool>> running;
  {
    Statement q(db_, "SELECT id, cancel_requested FROM jobs WHERE state = 'running'");
    while (q.step()) running.emplace_back(q.int64(0), q.int64(1) != 0);
  }
  for (const auto& [id, cancel] : running) {
    if (cancel)
      Statement(db_, "UPDATE jobs SET state = 'cancelled', finished_at = ? WHERE id = ?").bind(1, unix_now()).bind(2, id).run();
    else
      Statement(db_, "UPDATE jobs SET state = 'queued', started_at = NULL WHERE id = ?").bind(1, id).run();
    add_event_locked(id, cancel ? "cancelled" : "requeued", "interrupted while running (server restart)");
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
  add_event_locked(job_id, "interrupted", why);
  tx.commit();
}

void ResultStore::finish(std::int64_t job_id, JobState final_state, const std::string& error, double run_seconds,
                         double publish_seconds) {
  std::lock_guard lock(mutex_);
  Transaction tx(db_);
  Statement upd(db_,
                "UPDATE jobs SET state = ?, finished_at = ?, error = ?, run_seconds = run_seconds + ?, "
                "publish_seconds = publish_seconds + ? WHERE id = ?");
  upd.bind(1, to_string(final_state)).bind(2, unix_now());
  if (error.empty())
    upd.bind(3, std::nullopt);
  else
    upd.bind(3, error);
  upd.bind(4, run_seconds).bind(5, publish_seconds).bind(6, job_id).run();
  add_event_locked(job_id, std::string(to_string(final_state)), error);
  tx.commit();
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
                "iterations, status, values_json, solved_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?) "
                "ON CONFLICT (job_id, curve_index, point_index) DO NOTHING");
  ins.bind(1, job_id)
      .bind(2, std::int64_t{p.key.curve_index})
      .bind(3, std::int64_t{p.key.point_index})
      .bind(4, p.parameter)
      .bind(5, p.objective)
      .bind(6, p.constraint_violation)
      .bind(7, std::int64_t{p.iterations})
      .bind(8, p.status)
      .bind(9, p.values.dump())
      .bind(10, unix_now())
      .run();
  if (db_.changes() == 0) return false;
  if (p.trajectory) {
    Statement tr(db_, "INSERT INTO trajectories (solution_id, format, data) VALUES (?, 'json', ?)");
    tr.bind(1, db_.last_insert_rowid()).bind_blob(2, p.trajectory->dump()).run();
  }
  tx.commit();
  return true;
}

std::set<PointKey> ResultStore::stored_points(std::int64_t job_id) {
  std::lock_guard lock(mutex_);
  std::set<PointKey> keys;
  Statement q(db_, "SELECT curve_index, point_index FROM solutions WHERE job_id = ?");
  q.bind(1, job_id);
  while (q.step()) keys.insert({static_cast<int>(q.int64(0)), static_cast<int>(q.int64(1))});
  return keys;
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

std::optional<JobRecord> ResultStore::job(std::int64_t job_id) {
  std::lock_guard lock(mutex_);
  Statement q(db_, std::string("SELECT ") + kJobColumns + " FROM jobs j WHERE j.id = ?");
  if (!q.bind(1, job_id).step()) return std::nullopt;
  return read_job(q);
}

std::vector<JobRecord> ResultStore::jobs(std::optional<JobState> state, int offset, int limit) {
  std::lock_guard lock(mutex_);
  Statement q(db_, std::string("SELECT ") + kJobColumns +
                       " FROM jobs j WHERE (?1 IS NULL OR j.state = ?1) ORDER BY j.id LIMIT ?2 OFFSET ?3");
  if (state)
    q.bind(1, to_string(*state));
  else
    q.bind(1, std::nullopt);
  q.bind(2, std::int64_t{limit}).bind(3, std::int64_t{offset});
  std::vector<JobRecord> out;
  while (q.step()) out.push_back(read_job(q));
  return out;
}

int ResultStore::count_jobs(std::optional<JobState> state) {
  std::lock_guard lock(mutex_);
  Statement q(db_, "SELECT count(*) FROM jobs WHERE (?1 IS NULL OR state = ?1)");
  if (state)
    q.bind(1, to_string(*state));
  else
    q.bind(1, std::nullopt);
  q.step();
  return static_cast<int>(q.int64(0));
}

}  // namespace cyclopt::storage
