// Artifact time histories in HDF5, one file per run, beside the study's .sqlite file.
// Layout: group /artifact with 1-D double datasets time, u_mean, u_max, kinetic_energy; group
// /impactor (when the run kept it) with mass (one value), vx, vy, vz.
// The file is written under a temporary name and renamed into place, so a referenced file is
// either absent (the SQLite row is committed only after the rename) or complete.
#pragma once

#include <filesystem>

#include "records/run_record.hpp"

namespace ccm::db {

// The group holding the datasets, as stored in runs.history_dataset.
inline constexpr const char* kArtifactGroup = "/artifact";

// The group of the impactor's datasets.
inline constexpr const char* kImpactorGroup = "/impactor";

// Writes `history` (and a non-empty `impactor`) to `file` atomically (temporary file, then
// rename). Throws StoreError.
void write_history_file(const std::filesystem::path& file, const study::ArtifactHistory& history,
                        const study::ImpactorHistory& impactor = {});

// The impactor's datasets, or an empty history when the file has none (written before ccm kept
// them). Throws StoreError naming file and dataset.
study::ImpactorHistory read_impactor_history(const std::filesystem::path& file);

// Reads the datasets of `group` back. Throws StoreError naming file and dataset.
study::ArtifactHistory read_history_file(const std::filesystem::path& file,
                                         const char* group = kArtifactGroup);

}  // namespace ccm::db
