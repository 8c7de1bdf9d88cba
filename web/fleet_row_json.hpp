#pragma once
// One job as the dashboard's pages receive it (docs/dashboard.md): the fleet line of `cyclopt top`
// (client/fleet_table.hpp: the jobs query row with the live progress applied) plus what a browser
// shows beyond 80 columns - the failure reason, the queue position, the stored points - and the
// time of the progress message it shows (its latency is measured from there to the page).

#include "fleet_table.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <vector>

namespace cyclopt::web {

struct FleetRow {
  client::FleetJob job;
  std::string error;            // why a job failed or is incomplete (the jobs row's "error")
  bool cancel_requested = false;
  int queue_position = 0;       // 1 = next to start, for queued jobs; 0 otherwise
  int points_stored = 0;
  int points_total = -1;        // -1: not announced yet
  std::int64_t progress_us = 0;  // timestamp of the live progress message applied, 0: none
};

// A row of the `jobs` query (storage_read/result_queries.hpp).
FleetRow fleet_row(const nlohmann::json& job_row);

// Queued jobs start in the order of their ids (storage::ResultStore::claim_next takes the lowest first).
void number_queue(std::vector<FleetRow>& rows);

// Times as ISO 8601 local time of the server to the minute (as `cyclopt list`), NaN as null.
nlohmann::json to_json(const FleetRow& row);

}  // namespace cyclopt::web
