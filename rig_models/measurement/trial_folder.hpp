// Reading every measured trial of a folder (<CASE>_t<N>.csv files) before any simulation
// starts: all files are read and checked first, then grouped by case, each case's trials in
// trial order.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "rig_models/measurement/measured_trial.hpp"

namespace ccm::rig {

// Every *.csv of `folder`, by case code. Throws RigInputError for the first defective file
// (see trial_csv.hpp), for a trial without a number, for two files giving the same case and
// trial, and when the folder holds no CSV file or cannot be listed.
std::map<std::string, std::vector<MeasuredTrial>> read_trial_folder(
    const std::filesystem::path& folder);

}  // namespace ccm::rig
