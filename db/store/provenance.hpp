// Where and by what a run was produced; stored on every runs row.
#pragma once

#include <string>

namespace ccm::db {

struct RunProvenance {
  std::string ccm_version;  // CCM_VERSION
  std::string git_hash;     // CCM_GIT_HASH
  std::string grid_hash;    // content hash of the grid file
  std::string host;         // hostname
  long pid = 0;             // process that wrote the row
  int ranks = 1;            // MPI ranks of the study run
  int jobs = 1;             // local parallel jobs of the study run
};

// This build's version and git hash, this host and process; `grid_hash`, `ranks`, `jobs` as given.
RunProvenance current_provenance(const std::string& grid_hash, int ranks = 1, int jobs = 1);

// Now as ISO 8601 UTC with milliseconds, e.g. 2026-11-22T05:10:00.123Z.
std::string utc_now();

}  // namespace ccm::db
