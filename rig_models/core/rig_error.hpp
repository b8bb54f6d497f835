// Bad rig input (a measured CSV, the case file): a message that names the file, the line and
// the column or key, so a user can go straight to the defect.
#pragma once

#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>
#include <string_view>

namespace ccm::rig {

// The message reads "<file>:<line>: <where>: <problem>"; the line is left out when 0 and
// <where> (a column or a key path) when empty.
struct RigInputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline RigInputError rig_input_error(const std::filesystem::path& file, int line,
                                     std::string_view where, std::string_view problem) {
  std::string msg = file.string();
  if (line > 0) msg += fmt::format(":{}", line);
  if (!where.empty()) msg += fmt::format(": {}", where);
  return RigInputError(fmt::format("{}: {}", msg, problem));
}

}  // namespace ccm::rig
