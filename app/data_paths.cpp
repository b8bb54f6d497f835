#include "app/data_paths.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <system_error>

namespace ccm {
namespace {

namespace fs = std::filesystem;

// The file that marks a data folder.
constexpr std::string_view kMarker = "rig/cases.toml";

// The folder of the running executable (Linux: /proc/self/exe); empty when unknown.
fs::path executable_folder() {
  std::error_code error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", error);
  return error ? fs::path() : exe.parent_path();
}

std::vector<fs::path> candidates() {
  if (const char* dir = std::getenv("CCM_DATA_DIR"); dir && *dir) return {fs::path(dir)};
  const fs::path exe = executable_folder();
  if (exe.empty()) return {};
  return {(exe / CCM_DATA_DIR_FROM_BINDIR / "ccm").lexically_normal(), exe / "share" / "ccm"};
}

}  // namespace

DataFolder find_data_folder() {
  DataFolder folder;
  for (const fs::path& dir : candidates()) {
    folder.tried.push_back(dir);
    std::error_code ignored;
    if (fs::is_regular_file(dir / kMarker, ignored)) {
      folder.found = dir;
      break;
    }
  }
  return folder;
}

fs::path default_data_file(std::string_view relative) {
  const DataFolder folder = find_data_folder();
  return folder.found ? *folder.found / relative : fs::path();
}

std::string missing_data_message(std::string_view option) {
  std::vector<std::string> tried;
  for (const fs::path& dir : find_data_folder().tried) tried.push_back(dir.string());
  return fmt::format(
      "no ccm data folder holding {} (looked in {}): pass {} FILE, or set CCM_DATA_DIR to the "
      "installed share/ccm folder",
      kMarker,
      tried.empty() ? std::string("nowhere: the executable's path is unknown")
                    : fmt::format("{}", fmt::join(tried, ", ")),
      option);
}

}  // namespace ccm
