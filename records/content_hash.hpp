// Content hashes of what was run: stable across runs, machines and builds.
#pragma once

#include <string>
#include <string_view>

namespace ccm::study {

// FNV-1a 64 of the bytes, as 16 lowercase hex digits: the hash `ccm run` writes to summary.toml
// as scene_fnv1a64 (app/run_command.cpp uses this one).
std::string fnv1a64(std::string_view data);

}  // namespace ccm::study
