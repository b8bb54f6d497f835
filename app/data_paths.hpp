// Where ccm finds the data it ships (the rig's case and geometry files, the example scenes):
// relative to the executable, never at a path fixed when it was built, so that an installed
// prefix can be moved. The data folder is the first of
//   $CCM_DATA_DIR                        when set (then the only candidate);
//   <exe dir>/<bindir-to-datadir>/ccm    an installed tool: <prefix>/bin/ccm -> <prefix>/share/ccm
//   <exe dir>/share/ccm                  the build tree: <build>/ccm -> <build>/share/ccm, links
//                                        into the source tree (cmake/DataLayout.cmake)
// that holds rig/cases.toml.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ccm {

struct DataFolder {
  std::optional<std::filesystem::path> found;
  std::vector<std::filesystem::path> tried;  // in order, the found one last
};

DataFolder find_data_folder();

// The reference store ccm ships, relative to the data folder (scripts/build-reference-store.sh).
inline constexpr std::string_view kReferenceStore = "reference/whole-impacts.sqlite";

// The main job's store (scripts/run.sh): where `ccm compare` and `ccm validate` record without
// --db, when it exists.
inline constexpr const char* kMainJobStore = "results/default-study.sqlite";

// <data folder>/<relative>, or an empty path when there is no data folder.
std::filesystem::path default_data_file(std::string_view relative);

// "no ccm data folder with rig/cases.toml (looked in A, B): pass OPTION FILE or set
// CCM_DATA_DIR": the message when an option's default is missing.
std::string missing_data_message(std::string_view option);

}  // namespace ccm
