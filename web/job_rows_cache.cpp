#include "job_rows_cache.hpp"

#include "store_rows.hpp"

namespace cyclopt::web {

JobRowsCache::JobRowsCache(storage::ResultReader& store, std::map<std::string, Convert> kinds)
    : store_(store), kinds_(std::move(kinds)) {}

nlohmann::json JobRowsCache::rows_after(std::int64_t id, const std::string& what, std::size_t have, const std::string& mark) {
  const Convert& convert = kinds_.at(what);
  std::lock_guard lock(mutex_);
  Rows& cached = cache_[{id, what}];
  if (cached.mark != mark) {
    storage::QueryRequest request = storage::query_for(what, id);
    request.offset = static_cast<int>(cached.rows.size());
    for (const nlohmann::json& row : all_rows(store_, request)) cached.rows.push_back(convert(row));
    cached.mark = mark;
  }
  nlohmann::json after = nlohmann::json::array();
  for (std::size_t i = have; i < cached.rows.size(); ++i) after.push_back(cached.rows[i]);
  return after;
}

}  // namespace cyclopt::web
