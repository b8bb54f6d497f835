#include "study/provenance/version.hpp"

namespace ccm {

std::string version_string() { return std::string(CCM_VERSION) + " (git " + CCM_GIT_HASH + ")"; }

}  // namespace ccm
