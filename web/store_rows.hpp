#pragma once
// Every row of a query from `request.offset` on, read page by page from the read-only database
// (storage/result_queries.hpp caps a page at channels::kMaxQueryLimit rows).

#include "cyclopt/storage/result_queries.hpp"

namespace cyclopt::web {

nlohmann::json all_rows(storage::ResultStore& store, storage::QueryRequest request);

}  // namespace cyclopt::web
