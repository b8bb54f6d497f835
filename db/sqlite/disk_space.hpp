// What a failed write says about the disk: a store or history write that fails on a full file
// system names it, so that the user frees space rather than suspects the store.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace ccm::db {

// Below this many free bytes the file system holding a store is called full.
inline constexpr std::uintmax_t kFullBelowBytes = 1 << 20;

// " (the file system holding <folder> is full: N bytes free)" when the folder of `file` has fewer
// than kFullBelowBytes available, else "".
std::string disk_full_note(const std::filesystem::path& file);

}  // namespace ccm::db
