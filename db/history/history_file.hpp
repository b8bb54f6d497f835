// Artifact time histories in HDF5, one file per run, beside the study's .sqlite file.
// Layout: group /artifact with 1-D double datasets time, u_mean, u_max, kinetic_energy.
// The file is written under a temporary name and renamed into place, so a referenced file is
// either absent (the SQLite row is committed only after the rename) or complete.
#pragma once

#include <filesystem>

#include "records/run_record.hpp"

namespace ccm::db {

// The group holding the datasets, as stored in runs.history_dataset.
inline constexpr const char* kArtifactGroup = "/artifact";

// Writes `history` to `file` atomically (temporary file, then rename). Throws StoreError.
void write_history_file(const std::filesystem::path& file, const study::ArtifactHistory& history);

// Reads the datasets of `group` back. Throws StoreError naming file and dataset.
study::ArtifactHistory read_history_file(const std::filesystem::path& file,
                                         const char* group = kArtifactGroup);

}  // namespace ccm::db
