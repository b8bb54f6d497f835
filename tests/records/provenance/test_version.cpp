// The version and git hash are written at build time (cmake/VersionInfo.cmake): the hash is the
// source tree's HEAD at the last build, not at the last configure.
#include <array>
#include <catch2/catch.hpp>
#include <cstdio>
#include <memory>
#include <string>

#include "records/provenance/version.hpp"

namespace {

// `git rev-parse --short=12 HEAD` of the source tree, the command the build runs; "unknown"
// when git or the checkout is missing, as in the build.
std::string source_tree_head() {
  const std::string command =
      std::string("git -C '") + CCM_SOURCE_DIR + "' rev-parse --short=12 HEAD 2>/dev/null";
  std::unique_ptr<FILE, decltype(&pclose)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return "unknown";
  std::string out;
  std::array<char, 64> buffer{};
  while (fgets(buffer.data(), static_cast<int>(buffer.size()), pipe.get()) != nullptr)
    out += buffer.data();
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out.empty() ? "unknown" : out;
}

}  // namespace

TEST_CASE("version: the git hash is the source tree's HEAD at build time", "[provenance]") {
  CHECK(std::string(ccm::git_hash()) == source_tree_head());
  CHECK(std::string(ccm::ccm_version()) == CCM_PROJECT_VERSION);
  CHECK(ccm::version_string() ==
        std::string(ccm::ccm_version()) + " (git " + ccm::git_hash() + ")");
}
