#include "job_owners.hpp"

#include "cyclopt/storage_read/result_queries.hpp"

namespace cyclopt::server {

namespace {
constexpr const char* kSubmittedBy = "submitted_by";
}

void JobOwners::record(std::int64_t job_id, const wire::AuthKey& key) {
  store_.add_event(job_id, kSubmittedBy, key.id);
  std::lock_guard lock(mutex_);
  cache_[job_id] = key.id;
}

const wire::AuthKey* JobOwners::owner(std::int64_t job_id) {
  std::lock_guard lock(mutex_);
  auto it = cache_.find(job_id);
  if (it == cache_.end()) {
    std::string id;
    for (const auto& e : storage::run_query(store_, {"events", job_id, "", 0, 1000, std::nullopt}).rows)
      if (e["kind"] == kSubmittedBy) id = e["message"].get<std::string>();
    it = cache_.emplace(job_id, id).first;
  }
  return keys_.find(it->second);
}

}  // namespace cyclopt::server
