#include "cyclopt/storage_read/results_schema.hpp"

namespace cyclopt::storage {

std::string_view results_schema_sql() {
  return R"sql(
CREATE TABLE IF NOT EXISTS schema_info (key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS jobs (
  id INTEGER PRIMARY KEY,
  request_id TEXT NOT NULL UNIQUE,
  scene TEXT NOT NULL,
  task TEXT NOT NULL,
  spec_json TEXT NOT NULL,
  state TEXT NOT NULL DEFAULT 'queued'
    CHECK (state IN ('queued', 'running', 'done', 'failed', 'cancelled', 'incomplete')),
  cancel_requested INTEGER NOT NULL DEFAULT 0,
  attempts INTEGER NOT NULL DEFAULT 0,
  submitted_at REAL NOT NULL,
  started_at REAL,
  finished_at REAL,
  points_total INTEGER,
  run_seconds REAL NOT NULL DEFAULT 0,
  publish_seconds REAL NOT NULL DEFAULT 0,
  error TEXT,
  points_converged INTEGER,
  program_version TEXT NOT NULL DEFAULT '',
  seeds_json TEXT NOT NULL DEFAULT '{}',
  resolved_spec_json TEXT NOT NULL DEFAULT '',
  isa_level TEXT NOT NULL DEFAULT '',
  build_flags TEXT NOT NULL DEFAULT '',
  progress_percent REAL,
  phase TEXT NOT NULL DEFAULT '',
  eta_seconds REAL,
  best_objective REAL,
  progress_at REAL
);
CREATE INDEX IF NOT EXISTS jobs_by_state ON jobs (state, id);
CREATE TABLE IF NOT EXISTS events (
  id INTEGER PRIMARY KEY,
  job_id INTEGER NOT NULL REFERENCES jobs (id),
  at REAL NOT NULL,
  kind TEXT NOT NULL,
  message TEXT NOT NULL DEFAULT ''
);
CREATE INDEX IF NOT EXISTS events_by_job ON events (job_id, id);
CREATE TABLE IF NOT EXISTS curves (
  id INTEGER PRIMARY KEY,
  job_id INTEGER NOT NULL REFERENCES jobs (id),
  curve_index INTEGER NOT NULL,
  name TEXT NOT NULL,
  parameter_name TEXT NOT NULL,
  UNIQUE (job_id, curve_index)
);
CREATE TABLE IF NOT EXISTS solutions (
  id INTEGER PRIMARY KEY,
  job_id INTEGER NOT NULL REFERENCES jobs (id),
  curve_index INTEGER NOT NULL,
  point_index INTEGER NOT NULL,
  parameter REAL,
  objective REAL,
  constraint_violation REAL,
  iterations INTEGER,
  status TEXT NOT NULL,
  values_json TEXT NOT NULL,
  required INTEGER NOT NULL DEFAULT 1,
  solved_at REAL NOT NULL,
  UNIQUE (job_id, curve_index, point_index)
);
CREATE TABLE IF NOT EXISTS checkpoints (
  job_id INTEGER NOT NULL REFERENCES jobs (id),
  key TEXT NOT NULL,
  value TEXT NOT NULL,
  PRIMARY KEY (job_id, key)
);
CREATE TABLE IF NOT EXISTS trajectories (
  id INTEGER PRIMARY KEY,
  solution_id INTEGER NOT NULL UNIQUE REFERENCES solutions (id),
  format TEXT NOT NULL,
  data BLOB NOT NULL
);
)sql";
}

}  // namespace cyclopt::storage
