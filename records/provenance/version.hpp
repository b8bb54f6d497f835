// The ccm version and the git commit it was built from, for provenance in every output.
// The two values are written at build time into version_info.cpp in the build tree
// (cmake/VersionInfo.cmake), so they follow every commit without a new configure and only that
// one file recompiles when the commit changes.
#pragma once

#include <string>

namespace ccm {

const char* ccm_version();     // the project version, e.g. "0.1.0"
const char* git_hash();        // the 12-digit commit hash, or "unknown" outside a git checkout
std::string version_string();  // e.g. "0.1.0 (git 1a2b3c4d5e6f)"

}  // namespace ccm
