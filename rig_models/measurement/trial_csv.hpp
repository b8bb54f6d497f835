// Reading a measured trial CSV (docs/measurements.md). Accepts CRLF line
// endings, a UTF-8 byte-order mark, blank lines, columns in any order and unknown extra
// columns (ignored, with a warning). Refuses with RigInputError, naming file, line and
// column: an empty or header-only file, a wrong delimiter, a missing or repeated column, a
// row with the wrong number of cells, a non-numeric cell, a non-finite number, an empty time,
// time going backwards or repeating, a forward jump of the clock beyond 100 times the file's
// median step between rows (clock_jump.hpp), a row where no sensor sampled, a sensor with no
// sample at all, and a case code or trial number the metadata and the file name disagree on.
#pragma once

#include <filesystem>
#include <string_view>

#include "rig_models/measurement/measured_trial.hpp"

namespace ccm::rig {

// The required columns, by their names in the header.
inline constexpr std::string_view kTimeColumn = "time_s";
inline constexpr std::string_view kVelocityColumn = "impactor_velocity_mps";
inline constexpr std::string_view kAngleColumn = "artifact_angle_deg";
inline constexpr std::string_view kPressureColumn = "pressure_kpa";

// Parses the text of a trial file; `source` names it in messages and gives the case code and
// trial number when the name is <CASE>_t<N>.csv.
MeasuredTrial parse_trial_csv(std::string_view text, const std::filesystem::path& source);

// Reads and parses a trial file; also throws RigInputError when it cannot be read.
MeasuredTrial read_trial_csv(const std::filesystem::path& file);

}  // namespace ccm::rig
