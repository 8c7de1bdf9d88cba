#pragma once
// The spool directory through which cycloptd hands one work unit to a cyclopt-worker running
// elsewhere (a Slurm node) and reads its results back. It only needs a file system both see;
// every file is written atomically (temporary file, fsync, rename), so a reader never sees half
// a file, and a worker killed at any moment leaves only whole files behind.
//
//   DIR/unit.json          what to run: job id, task, spec, limits, the work unit of
//                          the job (JobKind::run_unit) or none: the whole job (server -> worker)
//   DIR/stored_keys.json   points the store already holds: skipped        (server -> worker)
//   DIR/checkpoints.json   the job's checkpoints the store holds: reused    (server -> worker)
//   DIR/events/NNNNNNNN.json  announce / curve / point / checkpoint, in order (worker -> server)
//   DIR/progress.json      the latest progress report                     (worker -> server)
//   DIR/cancel             present: stop at the next check                (server -> worker)
//   DIR/started.json       when the worker started (Unix seconds)         (worker -> server)
//   DIR/done.json          the worker's outcome: error text, stop reason  (worker -> server)
//
// The server is the only writer of the database: it ingests events idempotently (curves and
// points are keyed, re-ingesting a file changes nothing), so a re-run or re-attached unit never
// duplicates a point.

#include "cyclopt/service/job_context.hpp"
#include "cyclopt/storage_read/solution_point.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace cyclopt::server::remote {

struct UnitSpec {
  std::int64_t job_id = 0;
  std::string task;
  std::string spec_json;
  service::JobLimits limits;
  double run_seconds_before = 0.0;  // spent by earlier attempts; counts against limits.max_wall_seconds
  double submitted_at = 0.0;        // Unix seconds, just before sbatch (with started_at: queue latency)
  std::optional<service::WorkUnit> unit;  // the part of the job to compute; none: run the whole job
};

// One entry of the worker's event stream.
struct UnitEvent {
  enum class Type { announce, curve, point, checkpoint };
  Type type = Type::point;
  int points_total = -1;                      // announce
  int curve_index = 0;                        // curve
  std::string curve_name, parameter_name;     // curve
  storage::SolutionPoint point;               // point
  std::string checkpoint_key, checkpoint_value;  // checkpoint (JobContext::store_checkpoint)
};

struct UnitOutcome {
  std::string error;                          // empty: the kind returned normally
  service::StopReason stop = service::StopReason::none;
};

class UnitSpool {
 public:
  explicit UnitSpool(std::filesystem::path dir);
  const std::filesystem::path& dir() const { return dir_; }

  void create() const;  // the directory and events/
  void write_spec(const UnitSpec& spec) const;
  UnitSpec read_spec() const;  // throws std::runtime_error naming the file
  void write_stored_keys(const std::set<storage::PointKey>& keys) const;
  std::set<storage::PointKey> read_stored_keys() const;
  void write_checkpoints(const std::map<std::string, std::string>& checkpoints) const;
  std::map<std::string, std::string> read_checkpoints() const;

  // Appends an event as file number `sequence` (the worker counts from next_sequence()).
  void write_event(int sequence, const UnitEvent& event) const;
  int next_sequence() const;
  // Events numbered >= from, in order; stops at the first missing number.
  std::vector<std::pair<int, UnitEvent>> read_events(int from) const;

  void write_progress(const service::ProgressReport& report) const;
  std::optional<service::ProgressReport> read_progress() const;

  void write_started(double unix_seconds) const;
  std::optional<double> read_started() const;

  void request_cancel() const;
  bool cancel_requested() const;

  void write_outcome(const UnitOutcome& outcome) const;
  std::optional<UnitOutcome> read_outcome() const;
  // Before a (re)submission: the previous outcome, cancel request and progress go.
  void clear_run_state() const;

 private:
  std::filesystem::path dir_;
};

// Writes `text` to `path` through a temporary file in the same directory, fsync and rename.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

nlohmann::json point_to_json(const storage::SolutionPoint& p);
storage::SolutionPoint point_from_json(const nlohmann::json& j);  // throws nlohmann::json::exception

service::StopReason stop_reason_from_string(const std::string& s);

}  // namespace cyclopt::server::remote
