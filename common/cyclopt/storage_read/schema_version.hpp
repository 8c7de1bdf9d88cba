#pragma once
// The results schema version a database file records (schema_info.version, results_schema.hpp)
// and what an open does with it: a file of this build's version opens; an older one is migrated
// by a read-write open (storage/result_store.hpp) and refused by a read-only one
// (result_reader.hpp), which cannot write; a newer one (written by a later build) is refused.
// Refusals throw StorageError naming both versions.

#include "cyclopt/storage_read/sqlite_handle.hpp"

#include <optional>
#include <string>

namespace cyclopt::storage {

// nullopt for a file without schema_info (new, or empty); throws StorageError when the recorded
// version is not a positive integer.
std::optional<int> stored_schema_version(const Connection& db, const std::string& path);

// Throws StorageError unless a file at `version` may be opened (`read_only`: without migrating).
void check_schema_version(std::optional<int> version, const std::string& path, bool read_only);

}  // namespace cyclopt::storage
