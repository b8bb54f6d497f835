// Bad input in a configuration file (scene, grid, rig cases and geometry): one error type whose
// message names the file, the line and the key, "<file>:<line>: <key path>: <problem>".
#pragma once

#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ccm {

// The message reads "<file>:<line>: <key path>: <problem>".
struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "<file>:<line>: <key path>: <problem>"; the line is left out when 0, the key path when empty.
inline ConfigError config_error(const std::filesystem::path& file, int line,
                                std::string_view key_path, std::string_view problem) {
  std::string msg = file.string();
  if (line > 0) msg += fmt::format(":{}", line);
  if (!key_path.empty()) msg += fmt::format(": {}", key_path);
  return ConfigError(fmt::format("{}: {}", msg, problem));
}

}  // namespace ccm
