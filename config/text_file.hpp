// Reading a configuration file whole, with an error that names it.
#pragma once

#include <filesystem>
#include <string>

namespace ccm {

// The whole content of a file; throws ConfigError (config/config_error.hpp) naming it when it
// does not exist, is a directory or cannot be read.
std::string read_config_text(const std::filesystem::path& file);

}  // namespace ccm
