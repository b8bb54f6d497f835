// Reading trade-study grid files (TOML; the format is docs/grid-file.md) into a typed GridSpec.
#pragma once

#include <filesystem>
#include <string_view>

#include "study/grid/grid_spec.hpp"

namespace ccm::study {

// Parses the text of a grid file; `source` names it in messages. Throws ccm::ConfigError
// ("<file>:<line>: <key>: <problem>") on a syntax error, unknown key, wrong type, missing
// required key or value out of range.
GridSpec parse_grid(std::string_view text, const std::filesystem::path& source);

// Reads and parses a grid file. Throws ccm::ConfigError also when the file cannot be read.
GridSpec parse_grid_file(const std::filesystem::path& file);

}  // namespace ccm::study
