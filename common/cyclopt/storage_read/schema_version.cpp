#include "cyclopt/storage_read/schema_version.hpp"

#include "cyclopt/storage_read/results_schema.hpp"

#include <algorithm>
#include <cctype>

namespace cyclopt::storage {

std::optional<int> stored_schema_version(const Connection& db, const std::string& path) {
  {
    Statement table(db, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'schema_info'");
    if (!table.step()) return std::nullopt;
  }
  Statement q(db, "SELECT value FROM schema_info WHERE key = 'version'");
  if (!q.step()) return std::nullopt;
  const std::string text = q.text(0);
  const bool digits = !text.empty() && text.size() < 9 &&
                      std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
  if (!digits || std::stoi(text) < 1)
    throw StorageError("database '" + path + "': schema_info.version is '" + text +
                       "', not a results schema version (1.." + std::to_string(kSchemaVersion) + ")");
  return std::stoi(text);
}

void check_schema_version(std::optional<int> version, const std::string& path, bool read_only) {
  if (!version || *version == kSchemaVersion) return;
  const std::string found = "database '" + path + "' has results schema version " + std::to_string(*version);
  const std::string ours = "this build reads version " + std::to_string(kSchemaVersion);
  if (*version > kSchemaVersion)
    throw StorageError(found + ", newer than this build's " + std::to_string(kSchemaVersion) +
                       ": it was written by a later cyclopt; use that one (" + ours + ")");
  if (read_only)
    throw StorageError(found + "; " + ours + " and migrates older files when a server opens them read-write "
                       "(cycloptd --database '" + path + "'); a read-only open cannot migrate");
}

}  // namespace cyclopt::storage
