#pragma once
// What cyclopt-web knows of every job: the jobs table as last read (read-only) from the database,
// with each job's newest LCM progress message applied, as `cyclopt top` does. Every change gets a
// sequence number, so each open page (one SSE stream each) asks only for what changed since the
// last it sent, and waits on one condition variable. Thread-safe.

#include "fleet_row_json.hpp"

#include <cyclopt_lcm/job_progress_t.hpp>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <vector>

namespace cyclopt::web {

class LiveFleet {
 public:
  // Every row of the `jobs` query. A running job keeps the live progress it was sent.
  void refresh(const nlohmann::json& job_rows);
  void apply(const cyclopt_lcm::job_progress_t& progress);

  struct Changes {
    std::vector<FleetRow> rows;  // by id
    std::uint64_t seq = 0;       // to ask from next time
  };
  // The rows changed after `seq` (every row for 0).
  Changes rows_since(std::uint64_t seq) const;

  struct JobView {
    std::optional<FleetRow> row;                        // nullopt: not (yet) in the database
    std::optional<cyclopt_lcm::job_progress_t> progress;  // the newest message since cyclopt-web started
    std::uint64_t seq = 0;                              // of the newest change of either
  };
  JobView job(std::int64_t id) const;

  // Blocks until a change after `seq`, stop() or `timeout`; returns the newest sequence number.
  std::uint64_t wait(std::uint64_t seq, std::chrono::milliseconds timeout) const;
  // For the reader of the job list: blocks until a job ended, stop() or `timeout`. A job's last
  // progress message (100 %) follows the server's record of its end, so the list read then shows
  // its final state at once instead of "running 100 %" until the next periodic read.
  void wait_for_refresh(std::chrono::milliseconds timeout);
  void stop();
  bool stopped() const;

 private:
  struct Entry {
    std::optional<FleetRow> row;
    std::uint64_t row_seq = 0;
    std::optional<cyclopt_lcm::job_progress_t> progress;
    std::uint64_t progress_seq = 0;
  };
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::map<std::int64_t, Entry> jobs_;
  std::uint64_t seq_ = 0;
  bool stopped_ = false;
  bool refresh_due_ = false;  // a job ended since the list was last read
};

}  // namespace cyclopt::web
