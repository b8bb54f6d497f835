// Bad rig input (a measured CSV, the case file): a message that names the file, the line and
// the column or key, so a user can go straight to the defect. The same error type as every
// other configuration file (config/config_error.hpp).
#pragma once

#include "config/config_error.hpp"

namespace ccm::rig {

// The message reads "<file>:<line>: <where>: <problem>"; the line is left out when 0 and
// <where> (a column or a key path) when empty.
using RigInputError = ConfigError;

inline RigInputError rig_input_error(const std::filesystem::path& file, int line,
                                     std::string_view where, std::string_view problem) {
  return config_error(file, line, where, problem);
}

}  // namespace ccm::rig
