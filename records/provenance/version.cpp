#include "records/provenance/version.hpp"

namespace ccm {

// ccm_version() and git_hash() are defined in the generated version_info.cpp.
std::string version_string() { return std::string(ccm_version()) + " (git " + git_hash() + ")"; }

}  // namespace ccm
