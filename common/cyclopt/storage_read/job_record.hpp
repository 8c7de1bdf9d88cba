#pragma once
// One row of the jobs table (results_schema.hpp) as C++ sees it.

#include "cyclopt/storage_read/job_state.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace cyclopt::storage {

// A job's last recorded progress (results_schema.hpp): what a fleet view shows without LCM.
struct JobProgressRecord {
  std::optional<double> percent;  // 0..100, 100 only once the job ended done
  std::string phase;
  std::optional<double> eta_seconds;
  std::optional<double> best_objective;
  std::optional<double> at;       // Unix seconds
};

struct JobRecord {
  std::int64_t id = 0;
  std::string request_id;
  std::string scene;
  std::string task;
  std::string spec_json;
  JobState state = JobState::queued;
  bool cancel_requested = false;
  int attempts = 0;
  double submitted_at = 0.0;          // Unix seconds
  std::optional<double> started_at;
  std::optional<double> finished_at;
  std::optional<int> points_total;
  int points_stored = 0;              // rows in solutions
  std::optional<int> points_converged;  // required points that converged, set when the job ends
  double run_seconds = 0.0;
  double publish_seconds = 0.0;
  std::string error;
  std::string program_version;     // git revision of the accepting server ("" before schema 3)
  std::string seeds_json = "{}";   // random seeds by field of the resolved spec
  std::string resolved_spec_json;  // the spec with defaults filled in ("" before schema 3)
  std::string isa_level;           // instruction-set level of the accepting build ("" before schema 4)
  std::string build_flags;         // its compiler and code-generation flags ("" before schema 4)
  JobProgressRecord progress;      // the last recorded progress (schema 5)
};

}  // namespace cyclopt::storage
