// Reading scene files (TOML; the format is docs/scene-file.md) into a typed, validated Scene.
#pragma once

#include <filesystem>
#include <string_view>

#include "run/scene/scene.hpp"

namespace ccm {

// Parses the text of a scene file; `source` names it in messages and is the folder relative
// mesh file paths resolve against. Throws ConfigError on any syntax error, unknown key, wrong type,
// missing required key or value out of range.
Scene parse_scene(std::string_view text, const std::filesystem::path& source);

// Reads and parses a scene file. Throws ConfigError also when the file cannot be read.
Scene parse_scene_file(const std::filesystem::path& file);

}  // namespace ccm
