#pragma once
// The rows of a job that its open pages are sent (curves, points, events), read from the database
// once for all of them: ten pages of a running sweep cost one read per new point, not ten.
// Rows are appended only (a job's curves, points and events are never rewritten), so each page
// asks for the rows after the ones it has. Thread-safe.

#include "cyclopt/storage_read/result_reader.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <utility>

namespace cyclopt::web {

class JobRowsCache {
 public:
  // `what`: a row kind of storage::run_query ("curves", "solutions", "events"), each row stored as
  // `convert` makes it.
  using Convert = std::function<nlohmann::json(const nlohmann::json& row)>;
  JobRowsCache(storage::ResultReader& store, std::map<std::string, Convert> kinds);

  // The rows of `what` of job `id` after the first `have`. The database is read again only when
  // `mark` (what the caller knows of the job: its stored point count, its state) differs from the
  // mark of the last read.
  nlohmann::json rows_after(std::int64_t id, const std::string& what, std::size_t have, const std::string& mark);

 private:
  struct Rows {
    std::string mark;
    nlohmann::json rows = nlohmann::json::array();
  };
  storage::ResultReader& store_;
  const std::map<std::string, Convert> kinds_;
  std::mutex mutex_;
  std::map<std::pair<std::int64_t, std::string>, Rows> cache_;
};

}  // namespace cyclopt::web
