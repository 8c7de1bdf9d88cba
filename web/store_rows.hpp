#pragma once
// Every row of a query from `request.offset` on, read page by page from the read-only database
// (storage_read/result_queries.hpp caps a page at channels::kMaxQueryLimit rows).

#include "cyclopt/storage_read/result_queries.hpp"

namespace cyclopt::web {

nlohmann::json all_rows(storage::ResultReader& store, storage::QueryRequest request);

}  // namespace cyclopt::web
