// The store's schema as a list of migration steps (docs/store.md). PRAGMA user_version holds
// the number of steps applied; PRAGMA application_id marks the file as a ccm study store.
#pragma once

#include "db/sqlite/connection.hpp"

namespace ccm::db {

// "CCMS" in ASCII: written on creation, checked on every open.
inline constexpr int kApplicationId = 0x43434d53;

// Number of migration steps this build knows (= the schema version it writes).
int latest_schema_version();

// Schema version of an open file (PRAGMA user_version).
int schema_version(Connection& connection);

// Brings the file up to `target_version` (default: the latest), one transaction per step.
// A new, empty file is created at the target version. Throws StoreError, naming the file, when
// the file is not a ccm study store (foreign application_id, or tables without our id) or was
// written by a newer ccm (user_version above what this build knows).
void migrate(Connection& connection, int target_version = latest_schema_version());

// For reading an existing store without writing to it: throws StoreError, naming the file, when
// it is not a ccm study store (not SQLite, empty, another application's, without the ccm
// application_id) or was written by a newer ccm. Returns its schema version.
int check_existing_store(Connection& connection);

}  // namespace ccm::db
