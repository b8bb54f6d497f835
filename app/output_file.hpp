// Small pieces shared by the commands that write result files (`ccm run`, `ccm rig run`):
// a file written whole or not at all, and TOML scalars that read back exactly.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace ccm {

// Writes `content` to `<file>.partial`, then renames it to `file`: a reader sees the old file or
// the whole new one. Throws std::runtime_error naming the file when the write fails.
void write_atomic(const std::filesystem::path& file, std::string_view content);

// Refuses an output folder that cannot be made: throws std::invalid_argument "<option> <out>: ...
// is not writable (<reason>)" when the nearest existing folder on the way to `out` (`out` itself
// when it exists) is not writable. For the commands to check before any work.
void require_writable_output(const std::filesystem::path& out, std::string_view option);

// A TOML basic string: quotes, backslashes and control characters escaped.
std::string toml_string(std::string_view s);

// Shortest round-trip form, always a TOML float (never read back as an integer).
std::string toml_float(double v);

}  // namespace ccm
