// Reads the rig's records back from a store (schema step 3, docs/store.md), as
// db/store/rig_store.hpp wrote them: a run with its trials, its comparison (per channel and
// trial, the spreads over the trials, contact), its channels and the measured trials' channels;
// and the calibrations with their parameters and evaluations.
#pragma once

#include <vector>

#include "db/sqlite/connection.hpp"
#include "db/store/rig_store.hpp"

namespace ccm::db {

struct StoredRigRun {
  long long id = 0;
  RigRunRecord record;
};

// The ids of the latest rig run of purpose `purpose` per (case, drive), ordered by case and
// drive; empty when the store has none.
std::vector<long long> latest_rig_run_ids(Connection& connection, const char* purpose = "run");

// The run of that id, read whole. Throws StoreError when there is none.
StoredRigRun load_rig_run(Connection& connection, long long id);

// Every calibration, oldest first.
std::vector<RigCalibrationRecord> load_rig_calibrations(Connection& connection);

}  // namespace ccm::db
