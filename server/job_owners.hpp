#pragma once
// Which key submitted a job, when messages are authenticated (message_auth.hpp): recorded as
// the job's "submitted_by" event (so it survives restarts) and cached. Cancel is allowed to
// that key or an admin key; progress and done messages of the job are signed with it, so only
// its submitter can verify them. Thread-safe (workers sign progress concurrently).
#include "cyclopt/storage/result_store.hpp"
#include "message_auth.hpp"

#include <cstdint>
#include <map>
#include <mutex>
#include <string>

namespace cyclopt::server {

class JobOwners {
 public:
  JobOwners(const wire::KeyRing& keys, storage::ResultStore& store) : keys_(keys), store_(store) {}
  void record(std::int64_t job_id, const wire::AuthKey& key);
  // The submitter's key, or nullptr (a job submitted while authentication was off, or whose key
  // is no longer in the key file).
  const wire::AuthKey* owner(std::int64_t job_id);

 private:
  const wire::KeyRing& keys_;
  storage::ResultStore& store_;
  std::mutex mutex_;
  std::map<std::int64_t, std::string> cache_;
};

}  // namespace cyclopt::server
