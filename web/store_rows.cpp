#include "store_rows.hpp"

#include "cyclopt_channels.hpp"

namespace cyclopt::web {

nlohmann::json all_rows(storage::ResultReader& store, storage::QueryRequest request) {
  request.limit = channels::kMaxQueryLimit;
  nlohmann::json rows = nlohmann::json::array();
  while (true) {
    storage::QueryPage page = storage::run_query(store, request);
    for (nlohmann::json& row : page.rows) rows.push_back(std::move(row));
    request.offset += request.limit;
    if (page.rows.empty() || request.offset >= page.total) return rows;
  }
}

}  // namespace cyclopt::web
