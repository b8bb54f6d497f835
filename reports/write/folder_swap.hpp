// Replacing a folder whole: build the new content in a sibling staging folder, then rename.
#pragma once

#include <filesystem>

namespace ccm::reports {

// A fresh, empty sibling of `target` (".<name>.staging-<pid>"), replacing a stale one.
std::filesystem::path make_staging_folder(const std::filesystem::path& target);

// Moves `staging` to `target`: an existing `target` folder is renamed aside first and removed
// after the swap. Throws ReportError when `target` exists and is not a folder, or a rename
// fails.
void swap_in_folder(const std::filesystem::path& staging, const std::filesystem::path& target);

}  // namespace ccm::reports
