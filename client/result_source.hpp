#pragma once
// Where a client's queries go: a database file opened read-only (storage_read/result_queries.hpp run
// in this process) or cycloptd over LCM (ServiceClient, opened on first use with the key file's
// first key, else $CYCLOPT_KEY_FILE's). `cyclopt` and the Python package (python/) read results
// through it.

#include "cyclopt/storage_read/result_queries.hpp"
#include "cyclopt/storage_read/result_reader.hpp"
#include "service_client.hpp"

#include <lcm/lcm-cpp.hpp>

#include <optional>
#include <stdexcept>
#include <string>

namespace cyclopt::client {

// cycloptd did not answer within the timeout.
struct NoAnswer : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ResultSourceOptions {
  std::string database;  // read-only file; empty: ask the server
  std::string lcm_url;   // empty: $LCM_DEFAULT_URL or LCM's default (wire::resolved_lcm_url)
  std::string key_file;  // empty: $CYCLOPT_KEY_FILE, else unsigned
  double timeout = 10.0;  // s, for each query to the server
};

class ResultSource {
 public:
  explicit ResultSource(ResultSourceOptions options) : options_(std::move(options)) {}

  bool reads_database() const { return !options_.database.empty(); }
  // Every row a query matches (all pages); throws NoAnswer, QueryError, std::invalid_argument.
  storage::QueryPage fetch(storage::QueryRequest request);
  storage::ResultReader& local();
  ServiceClient& remote();

 private:
  ResultSourceOptions options_;
  std::optional<storage::ResultReader> store_;
  std::optional<lcm::LCM> lcm_;
  std::optional<ServiceClient> client_;
};

}  // namespace cyclopt::client
