// The rig a folder of measured trials was measured on: `rig.toml` beside the CSVs gives the
// values of that rig which differ from the case file's, first of all its pressure sensor's area
// and deadband (the thesis gives neither; a user's rig has its own). It holds one [rig] table
// with any of the case file's [rig] keys, each { value, unit, source } as there:
//
//   [rig]
//   sensor_area = { value = 2.5e-3, unit = "m^2", source = "our mat's 50 x 50 mm patch" }
//   sensor_deadband = { value = 0.5, unit = "kPa", source = "logger threshold" }
//
// Absent, the case file's values stand.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "rig_models/cases/rig_case.hpp"

namespace ccm::rig {

inline constexpr const char* kTrialRigFileName = "rig.toml";

struct TrialRigFile {
  std::filesystem::path path;
  std::string text;  // as read, for provenance
};

// Applies <folder>/rig.toml to `rig` when the file exists. Throws RigInputError naming the file,
// the line and the key for anything the case file would refuse, or an unknown key or table.
std::optional<TrialRigFile> apply_trial_rig_file(const std::filesystem::path& folder,
                                                 RigParameters& rig);

}  // namespace ccm::rig
