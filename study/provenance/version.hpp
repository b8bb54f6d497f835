// The ccm version and the git commit it was built from, for provenance in every output.
#pragma once

#include <string>

namespace ccm {

std::string version_string();  // e.g. "0.1.0 (git 1a2b3c4d5e6f)"

}  // namespace ccm
