#pragma once
// The read side shared by the server (answering query_request_t over LCM) and the client
// (reading a database file opened read-only): rows as JSON objects, paged.

#include "cyclopt/storage_read/job_record.hpp"
#include "cyclopt/storage_read/result_reader.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace cyclopt::storage {

struct QueryRequest {
  std::string what = "jobs";  // jobs | job | solutions | events | curves | trajectories
  std::int64_t job_id = 0;    // for everything but "jobs"
  std::string state;          // filter for "jobs"; empty = all
  int offset = 0;
  int limit = 100;
  std::optional<std::string> sender;  // filter for "jobs": only those this sender submitted (Submission::sender)
};

// All rows (from offset 0) of `what` for a job, or of the jobs in `state`.
QueryRequest query_for(std::string what, std::int64_t job_id = 0, std::string state = "");

struct QueryPage {
  nlohmann::json rows = nlohmann::json::array();
  int total = 0;  // rows matching the request, over all pages
};

// Throws std::invalid_argument naming the field ("what", "state", "job_id", "offset", "limit")
// and the admissible values.
QueryPage run_query(ResultReader& store, const QueryRequest& request);

nlohmann::json to_json(const JobRecord& job, bool with_spec);

// The row kinds that belong to one job (what `cyclopt export` collects besides the job row).
inline constexpr const char* kJobParts[] = {"events", "curves", "solutions", "trajectories"};

}  // namespace cyclopt::storage
